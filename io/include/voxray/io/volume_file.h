#pragma once
// Research volume formats: NIfTI-1/2 (.nii, .nii.gz), NRRD (.nrrd, .nhdr with detached raw or
// gzip data) and MetaImage (.mha, .mhd with .raw/.zraw). Geometry comes out in LPS like every
// Volume. Only std and GLM types here: the NIfTI library and ITK stay private to io.
#include <string>
#include <vector>

#include "voxray/io/load.h"
#include "voxray/io/volume.h"

namespace voxray {

// The file name endings these formats open with, lower case with the dot (".nii.gz", ...):
// for file dialogs and drop targets.
const std::vector<std::string>& volumeFileExtensions();

// True when PATH ends in one of volumeFileExtensions() (any case).
bool isVolumeFile(const std::string& path);

// Reads one 3D volume. A 4D file gives its first volume, with a warning saying so.
// Throws Error (Input) naming the file, what is wrong and what to do.
Volume importVolumeFile(const std::string& path, const LoadOptions& options = {});

}  // namespace voxray
