#include "cl_errors.h"

namespace voxray {

const char* clErrorName(int code) {
  switch (code) {
#define CASE(c, v) \
  case v:          \
    return #c;
    CASE(CL_SUCCESS, 0)
    CASE(CL_DEVICE_NOT_FOUND, -1)
    CASE(CL_DEVICE_NOT_AVAILABLE, -2)
    CASE(CL_COMPILER_NOT_AVAILABLE, -3)
    CASE(CL_MEM_OBJECT_ALLOCATION_FAILURE, -4)
    CASE(CL_OUT_OF_RESOURCES, -5)
    CASE(CL_OUT_OF_HOST_MEMORY, -6)
    CASE(CL_PROFILING_INFO_NOT_AVAILABLE, -7)
    CASE(CL_MEM_COPY_OVERLAP, -8)
    CASE(CL_IMAGE_FORMAT_MISMATCH, -9)
    CASE(CL_IMAGE_FORMAT_NOT_SUPPORTED, -10)
    CASE(CL_BUILD_PROGRAM_FAILURE, -11)
    CASE(CL_MAP_FAILURE, -12)
    CASE(CL_INVALID_VALUE, -30)
    CASE(CL_INVALID_DEVICE_TYPE, -31)
    CASE(CL_INVALID_PLATFORM, -32)
    CASE(CL_INVALID_DEVICE, -33)
    CASE(CL_INVALID_CONTEXT, -34)
    CASE(CL_INVALID_QUEUE_PROPERTIES, -35)
    CASE(CL_INVALID_COMMAND_QUEUE, -36)
    CASE(CL_INVALID_HOST_PTR, -37)
    CASE(CL_INVALID_MEM_OBJECT, -38)
    CASE(CL_INVALID_IMAGE_FORMAT_DESCRIPTOR, -39)
    CASE(CL_INVALID_IMAGE_SIZE, -40)
    CASE(CL_INVALID_SAMPLER, -41)
    CASE(CL_INVALID_BINARY, -42)
    CASE(CL_INVALID_BUILD_OPTIONS, -43)
    CASE(CL_INVALID_PROGRAM, -44)
    CASE(CL_INVALID_PROGRAM_EXECUTABLE, -45)
    CASE(CL_INVALID_KERNEL_NAME, -46)
    CASE(CL_INVALID_KERNEL_DEFINITION, -47)
    CASE(CL_INVALID_KERNEL, -48)
    CASE(CL_INVALID_ARG_INDEX, -49)
    CASE(CL_INVALID_ARG_VALUE, -50)
    CASE(CL_INVALID_ARG_SIZE, -51)
    CASE(CL_INVALID_KERNEL_ARGS, -52)
    CASE(CL_INVALID_WORK_DIMENSION, -53)
    CASE(CL_INVALID_WORK_GROUP_SIZE, -54)
    CASE(CL_INVALID_WORK_ITEM_SIZE, -55)
    CASE(CL_INVALID_GLOBAL_OFFSET, -56)
    CASE(CL_INVALID_EVENT_WAIT_LIST, -57)
    CASE(CL_INVALID_EVENT, -58)
    CASE(CL_INVALID_OPERATION, -59)
    CASE(CL_INVALID_BUFFER_SIZE, -61)
    CASE(CL_INVALID_GLOBAL_WORK_SIZE, -63)
    CASE(CL_PLATFORM_NOT_FOUND_KHR, -1001)
#undef CASE
    default:
      return "unknown OpenCL error";
  }
}

std::string clErrorMessage(const std::string& call, int code) {
  std::string msg = call + " failed: " + clErrorName(code) + " (" + std::to_string(code) + ")";
  switch (code) {
    case -1001:
    case -1:
      msg +=
          ". No OpenCL driver was found: install one, e.g. 'apt-get install pocl-opencl-icd' "
          "for the CPU, or your GPU vendor's OpenCL ICD";
      break;
    case -4:
    case -5:
    case -6:
      msg +=
          ". The device ran out of memory: try a smaller volume, a smaller image, or "
          "--device cpu";
      break;
    case -40:
      msg += ". The volume exceeds the device's largest 3D image: try --device cpu";
      break;
    default:
      break;
  }
  return msg;
}

}  // namespace voxray
