#pragma once
// OpenCL objects behind ClContext; only engine sources include this.
#include <condition_variable>
#include <map>
#include <mutex>
#include <set>
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
  // The program of `sourceName` built with `options` (built now unless cached). Builds run
  // outside the lock, so that a background build (ClContext::prebuild) does not hold up a
  // render whose kernels are built; a second caller of one program waits for the first.
  cl::Program program(const std::string& sourceName, const std::string& options);
  int programsBuilt();

 private:
  std::mutex mutex_;
  std::condition_variable built_;
  std::map<std::string, cl::Program> programs_;
  std::set<std::string> building_;
};

// Runs f, turning cl::Error into voxray::Error that names the call and the code.
template <class F>
auto clCall(F&& f) -> decltype(f());

}  // namespace voxray

#include "cl_call.inl"
