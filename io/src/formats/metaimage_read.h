#pragma once
// MetaImage (.mha, .mhd with .raw/.zraw) through ITK's MetaImageIO: TransformMatrix (its rows
// are the LPS directions of i, j, k) and Offset (the LPS centre of voxel 0) as ITK reads them.
#include <string>

#include "sample_grid.h"

namespace voxray::formats {

// AnatomicalOrientation only informs: when it disagrees with the TransformMatrix, the matrix
// is used and a warning says so. Throws Error (Input); ITK's exceptions are translated into a
// message naming the file.
SampleGrid readMetaImage(const std::string& path);

}  // namespace voxray::formats
