#pragma once
// Hidden temporary names beside a target, for writes that must appear whole or not at all
// (images, movies, DICOM objects, segmentation files): written there, then renamed.
#include <filesystem>
#include <string>

namespace voxray {

// Unique per process and call, with the target's extension kept so that writers choosing
// the format by extension still see it: "shot.png" -> ".shot.tmp4711-3.png".
std::filesystem::path temporaryBeside(const std::filesystem::path& target);

// The same, keeping EXTENSION whole where it has two parts that a library reads (".nii.gz",
// ".seg.nrrd"): "a.seg.nrrd", ".seg.nrrd" -> ".a.tmp4711-3.seg.nrrd". EXTENSION must end
// TARGET's file name (or be empty).
std::filesystem::path temporaryBeside(const std::filesystem::path& target,
                                      const std::string& extension);

}  // namespace voxray
