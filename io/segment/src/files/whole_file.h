#pragma once
// What the segmentation file writers and readers share: writing whole or not at all, and
// saying how a file's grid differs from the volume's.
#include <functional>
#include <string>

#include "voxray/io/segmentation.h"

namespace voxray::segfiles {

// Calls WRITE with a hidden temporary path beside PATH that keeps PATH's whole extension
// (".nii.gz", ".seg.nrrd": libraries choose compression by it), then renames it onto PATH.
// Refuses an existing PATH unless FORCE; removes the temporary file when WRITE throws.
void writeWhole(const std::string& path, bool force,
                const std::function<void(const std::string& temporary)>& write);

// ".nii.gz", ".seg.nrrd", ".nii", ".nrrd", ".dcm", ... (lower case); "" when none.
std::string wholeExtension(const std::string& path);

// Throws an Input error naming what differs (dims, spacing, origin or axes, with both values)
// when a label map read from PATH does not lie on the volume's grid.
void checkOnGrid(const VoxelGrid& file, const VoxelGrid& volume, const std::string& path);

}  // namespace voxray::segfiles
