#pragma once
// The OpenCL platform, device, context and queue Voxray renders with. Passed around as
// an object (no global singleton) so a test can pick PoCL and the app a GPU.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace voxray {

struct DeviceInfo {
  int index = 0;  // position in listDevices(); "--device N"
  std::string platform;
  std::string name;
  std::string vendor;
  std::string version;
  bool isGpu = false;
  bool imageSupport = false;
  size_t globalMemBytes = 0;
  size_t maxAllocBytes = 0;
  size_t maxImage3d[3] = {0, 0, 0};
  unsigned computeUnits = 0;
  unsigned nativeFloatWidth = 0;  // floats in the device's native vector (16: AVX-512)
};

// All devices of all platforms. Throws Error (Device) with an install hint when there is
// no OpenCL platform at all.
std::vector<DeviceInfo> listDevices();

struct ContextImpl;  // OpenCL objects stay out of public headers

class ClContext {
 public:
  // selector: "auto" (a GPU if there is one, else the CPU), "cpu", "gpu", or an index
  // from listDevices(). Empty = $VOXRAY_DEVICE, or "auto".
  explicit ClContext(const std::string& selector = "");
  ~ClContext();
  ClContext(const ClContext&) = delete;
  ClContext& operator=(const ClContext&) = delete;

  const DeviceInfo& device() const;
  ContextImpl& impl() { return *impl_; }
  // Builds kernels/SOURCENAME with -D OPTIONS (Raycaster::variantOptions) unless built, so
  // that the first frame needing it does not wait for the compiler. Thread-safe: another
  // thread may render meanwhile. Throws Error (Device) with the build log.
  void prebuild(const std::string& sourceName, const std::string& options);
  int programsBuilt() const;  // programs compiled so far (each source and options once)

  // Contexts on PARTS equal sub-devices of the device SELECTOR names (clCreateSubDevices,
  // CL_DEVICE_PARTITION_EQUALLY: PoCL's CPU split by cores), for one frame over several
  // devices (voxray/engine/multi_device.h). Empty when the device cannot be split into PARTS.
  static std::vector<std::unique_ptr<ClContext>> subDevices(const std::string& selector, int parts);

 private:
  struct Made {};  // subDevices() fills impl_ itself
  explicit ClContext(Made);
  std::unique_ptr<ContextImpl> impl_;
};

}  // namespace voxray
