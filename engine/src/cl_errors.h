#pragma once
// OpenCL status codes turned into messages a user can act on.
#include <string>

namespace voxray {

const char* clErrorName(int code);
// "clEnqueueNDRangeKernel failed: CL_OUT_OF_RESOURCES (-5)" plus a hint where one helps.
std::string clErrorMessage(const std::string& call, int code);

}  // namespace voxray
