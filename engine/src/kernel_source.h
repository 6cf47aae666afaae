#pragma once
// The kernels' OpenCL C, from the table embedded at build time (or from
// $VOXRAY_KERNEL_DIR while iterating on a kernel), with #include "folder/x.cl" (a path below
// kernels/, the table's key) resolved on the host so the device compiler needs no file system.
#include <string>

namespace voxray {

// Throws Error (Internal) when a file or an include is missing.
std::string kernelSource(const std::string& name);

}  // namespace voxray
