#include "voxray/engine/cl_context.h"

#include <cstdlib>

#include "cl_context_impl.h"
#include "cpu_worker_pinning.h"
#include "kernel_source.h"

namespace voxray {

namespace {

struct Found {
  cl::Platform platform;
  cl::Device device;
  DeviceInfo info;
};

std::vector<Found> enumerate() {
  pinCpuWorkersWhereSafe();  // before PoCL starts its workers
  std::vector<cl::Platform> platforms;
  cl_int err = cl::Platform::get(&platforms);
  if (err != CL_SUCCESS || platforms.empty())
    throw deviceError(clErrorMessage("clGetPlatformIDs", err == CL_SUCCESS ? -1001 : err));
  std::vector<Found> out;
  for (auto& pl : platforms) {
    std::vector<cl::Device> devices;
    try {
      pl.getDevices(CL_DEVICE_TYPE_ALL, &devices);
    } catch (const cl::Error&) {
      continue;  // a platform without devices is not an error while others have some
    }
    for (auto& d : devices) {
      DeviceInfo i;
      i.index = int(out.size());
      i.platform = pl.getInfo<CL_PLATFORM_NAME>();
      i.name = d.getInfo<CL_DEVICE_NAME>();
      i.vendor = d.getInfo<CL_DEVICE_VENDOR>();
      i.version = d.getInfo<CL_DEVICE_VERSION>();
      i.isGpu = (d.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_GPU) != 0;
      i.imageSupport = d.getInfo<CL_DEVICE_IMAGE_SUPPORT>() != 0;
      i.globalMemBytes = d.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
      i.maxAllocBytes = d.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
      if (i.imageSupport) {
        i.maxImage3d[0] = d.getInfo<CL_DEVICE_IMAGE3D_MAX_WIDTH>();
        i.maxImage3d[1] = d.getInfo<CL_DEVICE_IMAGE3D_MAX_HEIGHT>();
        i.maxImage3d[2] = d.getInfo<CL_DEVICE_IMAGE3D_MAX_DEPTH>();
      }
      i.computeUnits = d.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
      i.nativeFloatWidth = d.getInfo<CL_DEVICE_NATIVE_VECTOR_WIDTH_FLOAT>();
      out.push_back({pl, d, i});
    }
  }
  if (out.empty())
    throw deviceError(
        "OpenCL platforms were found but no devices: install a driver, e.g. "
        "'apt-get install pocl-opencl-icd' for the CPU");
  return out;
}

const Found& choose(const std::vector<Found>& all, const std::string& selector) {
  if (selector == "auto") {
    for (const auto& f : all)
      if (f.info.isGpu) return f;
    return all.front();
  }
  if (selector == "gpu" || selector == "cpu") {
    bool gpu = selector == "gpu";
    for (const auto& f : all)
      if (f.info.isGpu == gpu) return f;
    throw deviceError("no OpenCL " + selector + " device; 'voxray-cli devices' lists them");
  }
  char* end = nullptr;
  long n = std::strtol(selector.c_str(), &end, 10);
  if (selector.empty() || *end != '\0')
    throw inputError("--device: '" + selector + "' is not auto, cpu, gpu or a device number");
  if (n < 0 || n >= long(all.size()))
    throw inputError("--device: there is no device " + selector + " (there are " +
                     std::to_string(all.size()) + "; 'voxray-cli devices' lists them)");
  return all[size_t(n)];
}

}  // namespace

std::vector<DeviceInfo> listDevices() {
  return clCall([] {
    std::vector<DeviceInfo> out;
    for (const auto& f : enumerate()) out.push_back(f.info);
    return out;
  });
}

ClContext::ClContext(const std::string& selector) : impl_(std::make_unique<ContextImpl>()) {
  std::string sel = selector;
  if (sel.empty()) {
    const char* env = std::getenv("VOXRAY_DEVICE");
    sel = env && *env ? env : "auto";
  }
  clCall([&] {
    auto all = enumerate();
    const Found& f = choose(all, sel);
    impl_->info = f.info;
    impl_->device = f.device;
    impl_->context = cl::Context(f.device);
    impl_->queue = cl::CommandQueue(impl_->context, f.device, CL_QUEUE_PROFILING_ENABLE);
    return 0;
  });
}

ClContext::ClContext(Made) : impl_(std::make_unique<ContextImpl>()) {}

ClContext::~ClContext() = default;

std::vector<std::unique_ptr<ClContext>> ClContext::subDevices(const std::string& selector,
                                                              int parts) {
  ClContext parent(selector);
  const DeviceInfo& info = parent.device();
  std::vector<std::unique_ptr<ClContext>> out;
  if (parts < 1 || info.computeUnits < unsigned(parts)) return out;
  std::vector<cl::Device> subs;
  const cl_device_partition_property props[] = {
      CL_DEVICE_PARTITION_EQUALLY,
      cl_device_partition_property(info.computeUnits / unsigned(parts)), 0};
  try {
    parent.impl_->device.createSubDevices(props, &subs);
  } catch (const cl::Error&) {
    return out;  // the device does not partition (most GPUs): the caller uses whole devices
  }
  if (subs.size() < size_t(parts)) return out;
  clCall([&] {
    for (int k = 0; k < parts; ++k) {
      auto c = std::unique_ptr<ClContext>(new ClContext(Made{}));
      c->impl_->info = info;
      c->impl_->info.name = info.name + " (sub-device " + std::to_string(k + 1) + " of " +
                            std::to_string(parts) + ")";
      c->impl_->info.computeUnits = subs[size_t(k)].getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
      c->impl_->device = subs[size_t(k)];
      c->impl_->context = cl::Context(subs[size_t(k)]);
      c->impl_->queue =
          cl::CommandQueue(c->impl_->context, subs[size_t(k)], CL_QUEUE_PROFILING_ENABLE);
      out.push_back(std::move(c));
    }
    return 0;
  });
  return out;
}

const DeviceInfo& ClContext::device() const { return impl_->info; }

void ClContext::prebuild(const std::string& sourceName, const std::string& options) {
  impl_->program(sourceName, options);
}

int ClContext::programsBuilt() const { return impl_->programsBuilt(); }

int ContextImpl::programsBuilt() {
  std::lock_guard<std::mutex> lock(mutex_);
  return int(programs_.size());
}

cl::Program ContextImpl::program(const std::string& sourceName, const std::string& options) {
  const std::string key = sourceName + "|" + options;
  std::unique_lock<std::mutex> lock(mutex_);
  built_.wait(lock, [&] { return building_.count(key) == 0; });
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  building_.insert(key);
  lock.unlock();
  struct Done {  // wakes the waiters whether the build succeeded or threw
    ContextImpl& c;
    const std::string& key;
    ~Done() {
      {
        std::lock_guard<std::mutex> l(c.mutex_);
        c.building_.erase(key);
      }
      c.built_.notify_all();
    }
  };
  Done done{*this, key};
  cl::Program program(context, kernelSource(sourceName));
  {
    try {
      program.build({device}, options.c_str());
    } catch (const cl::Error& e) {
      std::string log;
      try {
        log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
      } catch (const cl::Error&) {
      }
      throw deviceError(
          clErrorMessage("clBuildProgram(" + sourceName + " " + options + ")", e.err()) +
          "\nbuild log for " + info.name + ":\n" + log);
    }
    std::lock_guard<std::mutex> l(mutex_);
    programs_.emplace(key, program);
  }
  return program;
}

cl::Kernel ContextImpl::kernel(const std::string& sourceName, const std::string& entry,
                               const std::string& options) {
  cl::Program p = program(sourceName, options);
  return clCall([&] { return cl::Kernel(p, entry.c_str()); });
}

}  // namespace voxray
