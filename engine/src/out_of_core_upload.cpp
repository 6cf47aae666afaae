// A part's slices to the device (out_of_core.h): Direct (blocking copies, in place on a CPU
// device) or Pinned (a staging ring and a transfer queue beside the kernels).
#include <algorithm>
#include <cstring>

#include "out_of_core_impl.h"
#include "voxray/io/error.h"
#include "voxray/io/parallel.h"

namespace voxray {

using ooc::Clock;

// Two pinned buffers of the largest part: one is filled from the source while the other's copy
// runs (a third would wait for the same part to leave the device: the eviction waits for the
// launch before). False where the runtime will not pin them: the parts then go Direct.
bool OutOfCoreRenderer::Impl::makeRing() {
  size_t bytes = 0;
  for (const Part& q : parts) bytes = std::max(bytes, q.bytes);
  try {
    clCall([&] {
      transfer = cl::CommandQueue(cl.context, cl.device, CL_QUEUE_PROFILING_ENABLE);
      ring.resize(2);
      for (Slot& slot : ring) {
        slot.host = cl::Buffer(cl.context, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR, bytes);
        slot.ptr = static_cast<int16_t*>(
            transfer.enqueueMapBuffer(slot.host, CL_TRUE, CL_MAP_WRITE, 0, bytes));
      }
      return 0;
    });
  } catch (const Error& e) {
    if (e.kind() != Error::Kind::Device) throw;
    for (Slot& slot : ring)
      if (slot.ptr) clCall([&] { return transfer.enqueueUnmapMemObject(slot.host, slot.ptr); });
    ring.clear();
    pinned = false;
    return false;
  }
  return true;
}

void OutOfCoreRenderer::Impl::harvest() {
  auto take = [](std::vector<cl::Event>& events, double& ms) {
    std::vector<cl::Event> running;
    for (const cl::Event& e : events) {
      try {
        if (e.getInfo<CL_EVENT_COMMAND_EXECUTION_STATUS>() != CL_COMPLETE) {
          running.push_back(e);
          continue;
        }
        ms += double(e.getProfilingInfo<CL_PROFILING_COMMAND_END>() -
                     e.getProfilingInfo<CL_PROFILING_COMMAND_START>()) *
              1e-6;  // nanoseconds
      } catch (const cl::Error&) {
        // no profiling on this queue: the frame's stats lack this time
      }
    }
    events = std::move(running);
  };
  take(kernelEvents, kernelMs);
  take(copyEvents, copyMs);
  for (Slot& slot : ring)
    if (slot.copied() && slot.copied.getInfo<CL_EVENT_COMMAND_EXECUTION_STATUS>() == CL_COMPLETE)
      slot.copied = cl::Event();
}

OutOfCoreRenderer::Impl::Spare OutOfCoreRenderer::Impl::takeSpare(size_t bytes) {
  Spare taken;
  for (size_t k = 0; k < spares.size(); ++k)
    if (spares[k].bytes == bytes) {
      taken = std::move(spares[k]);
      spares.erase(spares.begin() + std::ptrdiff_t(k));
      break;
    }
  // The others (another size: the parts at the volume's ends have one apron) are released once
  // their launches are done, as Direct releases every evicted part.
  for (Spare& spare : spares)
    if (spare.lastUse()) freeing.push_back(spare.lastUse);
  return taken;
}

void OutOfCoreRenderer::Impl::uploadPinned(Part& part, OutOfCoreStats& s) {
  const PartRange& r = part.range;
  const glm::ivec3 n = geom.dims;
  const int slices = r.storedEnd - r.storedFirst;
  Slot& slot = ring[ringNext];
  ringNext = (ringNext + 1) % ring.size();
  if (slot.copied()) clCall([&] { return slot.copied.wait(); });
  const auto t0 = Clock::now();
  if (const int16_t* in = src.slicesInPlace(r.storedFirst)) {
    // Slices in host memory: copied on every core (one core's memcpy, 5-10 GB/s, would be
    // slower than the bus the pinned copy runs at).
    const size_t bytes = part.bytes, pieces = 64, piece = (bytes / pieces + 4095) / 4096 * 4096;
    auto* to = reinterpret_cast<char*>(slot.ptr);
    const auto* from = reinterpret_cast<const char*>(in);
    parallelFor(pieces, [&](size_t k) {
      const size_t at = std::min(k * piece, bytes), end = std::min(at + piece, bytes);
      std::memcpy(to + at, from + at, end - at);
    });
  } else {
    src.readSlices(r.storedFirst, r.storedEnd, slot.ptr);
  }
  // The empty-space cells and the range from the slices as the Direct path learns them.
  if (rowsKnown < int(rowKnown.size())) learnRows(slot.ptr, r.storedFirst, r.storedEnd);
  s.readMs += msSince(t0);
  // An evicted part's memory of this size is reused: its copy waits on the device for that
  // part's last launch. The others' memory is free once their last launches are done: wait for
  // those alone (the part drawn just before, in a frame that evicts in order) so that the
  // budget is what the device holds; the read above ran while they did.
  Spare spare = takeSpare(part.bytes);
  if (!freeing.empty()) {
    clCall([&] { return cl::WaitForEvents(freeing); });
    freeing.clear();
    clCall([&] {
      harvest();
      return 0;
    });
  }
  spares.clear();  // their launches are done: released without waiting
  evictedPending = false;
  cl::Event copied;
  std::vector<cl::Event> after;
  if (spare.lastUse()) after.push_back(spare.lastUse);
  const std::vector<cl::Event>* wait = after.empty() ? nullptr : &after;
  if (!spare.buffer() && !spare.image()) ++s.allocations;
  try {
    clCall([&] {
      if (storage == VolumeStorage::Image3d) {
        cl::ImageFormat format(CL_R, CL_SNORM_INT16);  // as DeviceVolume: the kernel scales back
        part.image = spare.image() ? spare.image
                                   : cl::Image3D(cl.context, CL_MEM_READ_ONLY, format, size_t(n.x),
                                                 size_t(n.y), size_t(slices));
        transfer.enqueueWriteImage(part.image, CL_FALSE, {0, 0, 0},
                                   {size_t(n.x), size_t(n.y), size_t(slices)}, 0, 0, slot.ptr, wait,
                                   &copied);
      } else {
        part.buffer =
            spare.buffer() ? spare.buffer : cl::Buffer(cl.context, CL_MEM_READ_ONLY, part.bytes);
        transfer.enqueueWriteBuffer(part.buffer, CL_FALSE, 0, part.bytes, slot.ptr, wait, &copied);
      }
      transfer.flush();
      return 0;
    });
  } catch (const Error&) {
    part.buffer = cl::Buffer();
    part.image = cl::Image3D();
    throw;
  }
  slot.copied = copied;
  part.ready = copied;
  copyEvents.push_back(copied);
}

void OutOfCoreRenderer::Impl::upload(Part& part, OutOfCoreStats& s) {
  const PartRange& r = part.range;
  const glm::ivec3 n = geom.dims;
  const int slices = r.storedEnd - r.storedFirst;
  if (o.faultDeviceParts >= 0 && std::count_if(parts.begin(), parts.end(), [](const Part& q) {
                                   return q.resident;
                                 }) >= o.faultDeviceParts)
    throw deviceError(
        "clCreateBuffer failed: CL_MEM_OBJECT_ALLOCATION_FAILURE (-4) (the fault "
        "hook: the device takes " +
        std::to_string(o.faultDeviceParts) + " parts)");
  if (pinned && (!ring.empty() || makeRing())) {
    uploadPinned(part, s);
    s.pinned = true;
    ++uploadsDone;
    ++s.uploads;
    s.bytesUploaded += part.bytes;
    part.resident = true;
    residentBytes += part.bytes;
    return;
  }
  const auto t0 = Clock::now();
  const int16_t* in = nullptr;
  const bool image = storage == VolumeStorage::Image3d;
  // A CPU device reads slices already in host memory where they are (as DeviceVolume does).
  if (!cl.info.isGpu && !image) in = src.slicesInPlace(r.storedFirst);
  if (!in) {
    staging.resize(size_t(slices) * size_t(n.x) * size_t(n.y));
    src.readSlices(r.storedFirst, r.storedEnd, staging.data());
    in = staging.data();
  }
  if (rowsKnown < int(rowKnown.size())) learnRows(in, r.storedFirst, r.storedEnd);
  const auto t1 = Clock::now();
  s.readMs += std::chrono::duration<double, std::milli>(t1 - t0).count();
  // An evicted part's memory is freed once the launches queued on it are done: wait for them
  // (after the read above, which overlaps them) so that the budget is what the device holds.
  if (evictedPending) {
    clCall([&] {
      cl.queue.finish();
      harvest();
      return 0;
    });
    evictedPending = false;
    freeing.clear();
  }
  const auto t2 = Clock::now();  // the copy alone, not the wait for the queued parts
  ++s.allocations;
  clCall([&] {
    auto* ptr = const_cast<int16_t*>(in);
    if (image) {
      cl::ImageFormat format(CL_R, CL_SNORM_INT16);  // as DeviceVolume: the kernel scales back
      part.image = cl::Image3D(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, format,
                               size_t(n.x), size_t(n.y), size_t(slices), 0, 0, ptr);
    } else {
      const cl_mem_flags where = in == staging.data() ? CL_MEM_COPY_HOST_PTR : CL_MEM_USE_HOST_PTR;
      part.buffer = cl::Buffer(cl.context, CL_MEM_READ_ONLY | where, part.bytes, ptr);
    }
    return 0;
  });
  s.uploadMs += msSince(t2);
  ++uploadsDone;
  ++s.uploads;
  s.bytesUploaded += part.bytes;
  part.resident = true;
  residentBytes += part.bytes;
}

}  // namespace voxray
