#pragma once
// OpenCL objects behind ClContext; only engine sources include this.
#include <map>
#include <mutex>
#include <string>

#include <CL/opencl.hpp>

#include "voxray/engine/cl_context.h"

namespace voxray {

struct ContextImpl {
  DeviceInfo info;
  cl::Device device;
  cl::Context context;
  cl::CommandQueue queue;  // in order, profiling on

  // Builds (or returns the cached) kernel `entry` of `sourceName` with -D `options`.
  // Throws Error (Device) with the build log.
  cl::Kernel kernel(const std::string& sourceName, const std::string& entry,
                    const std::string& options);

 private:
  std::mutex mutex_;
  std::map<std::string, cl::Program> programs_;
};

// Runs f, turning cl::Error into voxray::Error that names the call and the code.
template <class F>
auto clCall(F&& f) -> decltype(f());

}  // namespace voxray

#include "cl_call.inl"
