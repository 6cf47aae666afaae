#include "device_volume.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "cl_context_impl.h"
#include "voxray/engine/volume_storage.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

std::string mibRoundedUp(size_t bytes) {
  return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB";
}

std::atomic<int> uploads{0};  // deviceVolumeUploads()

// One z slab's slices written from the volume's memory in blocking writes of at most
// kUploadChunkBytes each, instead of a buffer made with CL_MEM_COPY_HOST_PTR: a driver may
// stage (or keep) a whole copy of what it is handed at once, and the host would then hold the
// volume twice (issue 38: 17.1 GiB for an 8 GiB volume on an H100). Blocking, so that at most
// one chunk is in flight and what the driver stages stays bounded by it.
constexpr size_t kUploadChunkBytes = size_t(64) << 20;

size_t chunkSlices(glm::ivec3 n) {
  const size_t slice = size_t(n.x) * size_t(n.y) * sizeof(int16_t);
  return std::max<size_t>(1, kUploadChunkBytes / slice);
}

void writeInChunks(cl::CommandQueue& q, cl::Buffer& b, const int16_t* first, glm::ivec3 n,
                   int slices) {
  const size_t slice = size_t(n.x) * size_t(n.y) * sizeof(int16_t), step = chunkSlices(n);
  for (size_t z = 0; z < size_t(slices); z += step) {
    const size_t count = std::min(step, size_t(slices) - z);
    q.enqueueWriteBuffer(b, CL_TRUE, z * slice, count * slice,
                         reinterpret_cast<const uint8_t*>(first) + z * slice);
  }
}

void writeInChunks(cl::CommandQueue& q, cl::Image3D& image, const int16_t* first, glm::ivec3 n,
                   int slices) {
  const size_t slice = size_t(n.x) * size_t(n.y), step = chunkSlices(n);
  for (size_t z = 0; z < size_t(slices); z += step) {
    const size_t count = std::min(step, size_t(slices) - z);
    q.enqueueWriteImage(image, CL_TRUE, {0, 0, z}, {size_t(n.x), size_t(n.y), count}, 0, 0,
                        first + z * slice);
  }
}

}  // namespace

int deviceVolumeUploads() { return uploads.load(); }

void DeviceVolume::upload(ContextImpl& cl, const Volume& volume, VolumeStorage storage,
                          size_t maxSlabBytes) {
  ++uploads;
  const DeviceInfo& d = cl.info;
  const glm::ivec3 n = volume.dims;
  std::string dims = std::to_string(n.x) + "x" + std::to_string(n.y) + "x" + std::to_string(n.z);
  bool image = storage == VolumeStorage::Image3d;
  if (image) {
    if (!d.imageSupport)
      throw deviceError(d.name + " has no image support: render with the buffer storage");
    // Slabs split z only.
    if (size_t(n.x) > d.maxImage3d[0] || size_t(n.y) > d.maxImage3d[1])
      throw deviceError("the volume (" + dims + ") exceeds " + d.name + "'s largest 3D image (" +
                        std::to_string(d.maxImage3d[0]) + "x" + std::to_string(d.maxImage3d[1]) +
                        "x" + std::to_string(d.maxImage3d[2]) + "): try --device cpu");
  }
  size_t sliceBytes = size_t(n.x) * size_t(n.y) * sizeof(int16_t);
  size_t limit = d.maxAllocBytes;
  std::string limitText = d.name + "'s largest allocation (" + mibRoundedUp(limit) + ")";
  if (maxSlabBytes > 0 && maxSlabBytes < limit) {
    limit = maxSlabBytes;
    limitText = "the slab limit (" + mibRoundedUp(limit) + ")";
  }
  size_t maxSlices = limit / sliceBytes;
  if (image && d.maxImage3d[2] < maxSlices) {
    maxSlices = d.maxImage3d[2];
    limitText = d.name + "'s largest 3D image depth (" + std::to_string(maxSlices) + " slices)";
  }
  std::optional<SlabPlan> plan = planSlabs(n.z, maxSlices);
  if (!plan)
    throw deviceError("the volume (" + dims + ", " + mibRoundedUp(volume.byteSize()) +
                      ") exceeds " + limitText + " and does not split into " +
                      std::to_string(SlabPlan::kMaxSlabs) + " slabs of " +
                      std::to_string(maxSlices) + " slices (" + mibRoundedUp(sliceBytes) +
                      " each) within it: crop or downsample it, or use a device with more memory");
  plan_ = *plan;
  buffers_.clear();
  images_.clear();
  const auto t0 = std::chrono::steady_clock::now();
  clCall([&] {
    for (const SlabPlan::Slab& s : plan_.slabs) {
      auto* first = const_cast<int16_t*>(volume.voxels.data()) + size_t(s.first) * n.x * n.y;
      if (image) {
        // SNORM so the hardware filters it; the kernel scales back by 32767.
        cl::ImageFormat format(CL_R, CL_SNORM_INT16);
        images_.emplace_back(cl.context, CL_MEM_READ_ONLY, format, size_t(n.x), size_t(n.y),
                             size_t(s.stored));
        writeInChunks(cl.queue, images_.back(), first, n, s.stored);
      } else if (!d.isGpu) {
        // A CPU device reads host memory anyway: use the volume where it is instead of a
        // second copy (peak memory stays near the volume's size; slabs overlap by their
        // aprons). The Volume outlives us.
        buffers_.emplace_back(cl.context, CL_MEM_READ_ONLY | CL_MEM_USE_HOST_PTR,
                              size_t(s.stored) * sliceBytes, first);
      } else {
        buffers_.emplace_back(cl.context, CL_MEM_READ_ONLY, size_t(s.stored) * sliceBytes);
        writeInChunks(cl.queue, buffers_.back(), first, n, s.stored);
      }
    }
    return 0;
  });
  uploadMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

cl_uint DeviceVolume::setArgs(cl::Kernel& kernel, cl_uint first) const {
  for (const cl::Image3D& i : images_) kernel.setArg(first++, i);
  for (const cl::Buffer& b : buffers_) kernel.setArg(first++, b);
  return first;
}

}  // namespace voxray
