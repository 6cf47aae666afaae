#pragma once
// MetaImage (.mha, .mhd with .raw/.zraw) through MetaIO (ITK's MetaIO library, used on its
// own: Debian's ITK headers compile with GCC only, MetaIO's with any compiler). Geometry as
// ITK and 3D Slicer read it: TransformMatrix rows are the LPS directions of i, j, k; Offset
// (Position) is the LPS centre of voxel 0.
#include <string>

#include "sample_grid.h"

namespace voxray::formats {

// AnatomicalOrientation only informs: when it disagrees with the TransformMatrix, the matrix
// is used and a warning says so. Throws Error (Input).
SampleGrid readMetaImage(const std::string& path);

}  // namespace voxray::formats
