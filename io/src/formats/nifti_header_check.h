#pragma once
// A NIfTI header checked by our own code before the NIfTI library reads it: libnifti2 2.1
// overruns its stack on some invalid byte-swapped NIfTI-2 headers, in nifti_image_read and in
// nifti_read_header alike (tests/fuzz/regressions/nifti2-swapped-header-stack-overrun.nii).
#include <string>

namespace voxray::formats {

// Empty when the header at PATH (plain or gzip) is plausible: sizeof_hdr 348 or 540 in either
// byte order, its magic, dim[0] in 1 ... 7 with every used dim >= 1, and a known datatype.
// Otherwise what is wrong, for the caller's message.
std::string niftiHeaderProblem(const std::string& path);

}  // namespace voxray::formats
