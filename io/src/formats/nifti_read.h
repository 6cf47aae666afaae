#pragma once
// NIfTI-1 and NIfTI-2 (.nii, .nii.gz, .hdr/.img) through the NIfTI C library (libnifti2).
#include <string>

#include "sample_grid.h"

namespace voxray::formats {

// Geometry follows the NIfTI rule: the sform when its sform_code is set, else the qform;
// RAS+ becomes LPS. Throws Error (Input).
SampleGrid readNifti(const std::string& path);

}  // namespace voxray::formats
