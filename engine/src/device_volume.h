#pragma once
// The volume on the device: one buffer or 3D image, or one per z slab (slab_plan.h) when
// it exceeds the device's largest allocation or 3D image.
#include <vector>

#include <CL/opencl.hpp>

#include "slab_plan.h"

namespace voxray {

struct ContextImpl;
struct Volume;
enum class VolumeStorage;

class DeviceVolume {
 public:
  // storage: Buffer or Image3d. maxSlabBytes: 0 for the device's largest allocation.
  // On a CPU device buffers use the volume's memory in place (the Volume must outlive
  // this). Throws Error (Device) when the volume cannot be split within the limits.
  void upload(ContextImpl& cl, const Volume& volume, VolumeStorage storage, size_t maxSlabBytes);
  const SlabPlan& plan() const { return plan_; }
  // Wall time of the last upload (buffers made and the voxels written), for bench timings.
  double uploadMs() const { return uploadMs_; }
  // Sets the kernel arguments vol0 .. from index `first`; returns the next free index.
  cl_uint setArgs(cl::Kernel& kernel, cl_uint first) const;

 private:
  SlabPlan plan_;
  double uploadMs_ = 0.0;
  std::vector<cl::Buffer> buffers_;
  std::vector<cl::Image3D> images_;
};

}  // namespace voxray
