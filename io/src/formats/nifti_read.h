#pragma once
// NIfTI-1 and NIfTI-2 (.nii, .nii.gz, .hdr/.img) through the NIfTI C library (libnifti2).
#include <string>

#include "sample_grid.h"

namespace voxray::formats {

// Geometry follows the NIfTI rule: the sform when its sform_code is set, else the qform;
// RAS+ becomes LPS. TIME_POINT: which 3D volume of a 4D file (the product of dim[4..7]) is
// read; only that one is. Throws Error (Input), also for a time point out of range.
SampleGrid readNifti(const std::string& path, int timePoint = 0);

}  // namespace voxray::formats
