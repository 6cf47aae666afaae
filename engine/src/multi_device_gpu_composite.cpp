#include "multi_device_gpu_composite.h"

#include <algorithm>

namespace voxray {

std::vector<FrameBand> frameBands(int height, int count, int rowStep) {
  // About 256 rows a band: a 4K frame's 8 bands each move 8 MB a part, short next to the
  // kernel, so the transfers of the last band are what the frame waits for beyond the kernels.
  if (count <= 0) count = std::clamp(height / 256, 1, 8);
  rowStep = std::max(rowStep, 1);
  int rows = (height + count - 1) / count;
  rows = (rows + rowStep - 1) / rowStep * rowStep;
  std::vector<FrameBand> out;
  for (int first = 0; first < height; first += rows)
    out.push_back({first, std::min(rows, height - first)});
  return out;
}

DeviceCompositor::DeviceCompositor(const std::vector<ContextImpl*>& contexts)
    : first_(*contexts.front()) {
  clCall([&] {
    transfers_ = cl::CommandQueue(first_.context, first_.device, CL_QUEUE_PROFILING_ENABLE);
    links_.resize(contexts.size());
    for (size_t k = 1; k < contexts.size(); ++k) {
      links_[k].cl = contexts[k];
      links_[k].copies = cl::CommandQueue(contexts[k]->context, contexts[k]->device, 0);
    }
    return 0;
  });
}

DeviceCompositor::~DeviceCompositor() { unmap(); }

void DeviceCompositor::unmap() {
  for (Link& l : links_) {
    if (!l.host) continue;
    try {
      l.copies.enqueueUnmapMemObject(l.pinned, l.host);
      l.copies.finish();
    } catch (const cl::Error&) {
      // the buffer goes with its context; nothing else to do while tearing down
    }
    l.host = nullptr;
  }
}

void DeviceCompositor::reserve(size_t pixels) {
  if (pixels <= capacity_) return;
  unmap();
  const size_t halfBytes = pixels * 4 * sizeof(cl_half);
  clCall([&] {
    for (size_t k = 1; k < links_.size(); ++k) {
      Link& l = links_[k];
      l.device = cl::Buffer(l.cl->context, CL_MEM_READ_WRITE, halfBytes);
      // Pinned (mapped once): the GPU reads back at the bus's speed.
      l.pinned = cl::Buffer(l.cl->context, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR, halfBytes);
      l.host =
          l.copies.enqueueMapBuffer(l.pinned, CL_TRUE, CL_MAP_READ | CL_MAP_WRITE, 0, halfBytes);
    }
    const size_t others = std::max<size_t>(links_.size() - 1, 1) * halfBytes;
    others_ = cl::Buffer(first_.context, CL_MEM_READ_ONLY, others);
    rgba_ = cl::Buffer(first_.context, CL_MEM_WRITE_ONLY, pixels * 4);
    return 0;
  });
  capacity_ = pixels;
}

void DeviceCompositor::beginFrame() {
  for (Link& l : links_) l.read.clear();
}

void DeviceCompositor::readBand(size_t k, int width, const FrameBand& band,
                                const cl::Event& kernel) {
  Link& l = links_[k];
  const size_t bytes = size_t(width) * size_t(band.rows) * 4 * sizeof(cl_half);
  const size_t at = size_t(width) * size_t(band.first) * 4 * sizeof(cl_half);
  std::vector<cl::Event> after{kernel};
  cl::Event read;
  l.copies.enqueueReadBuffer(l.device, CL_FALSE, at, bytes, static_cast<char*>(l.host) + at, &after,
                             &read);
  l.copies.flush();
  l.read.push_back(read);
}

void DeviceCompositor::compositeBand(Mode mode, const std::vector<int>& order, glm::vec3 background,
                                     float earlyTermination, const cl::Buffer& own,
                                     const cl::Event& ownDone, int width, int height,
                                     const FrameBand& band, size_t bandIndex, uint8_t* out) {
  const size_t pixels = size_t(width) * size_t(height);
  const size_t bandPixels = size_t(width) * size_t(band.rows);
  const size_t halfPixel = 4 * sizeof(cl_half);
  std::vector<cl::Event> before{ownDone};
  for (size_t k = 1; k < links_.size(); ++k) {
    Link& l = links_[k];
    // Another context's event: the host waits (an event of one context cannot be in the wait
    // list of another's queue).
    l.read[bandIndex].wait();
    const size_t at = size_t(width) * size_t(band.first) * halfPixel;
    cl::Event up;
    transfers_.enqueueWriteBuffer(others_, CL_FALSE, (k - 1) * pixels * halfPixel + at,
                                  bandPixels * halfPixel, static_cast<char*>(l.host) + at, nullptr,
                                  &up);
    before.push_back(up);
  }
  const int modeIndex = mode == Mode::Iso ? 0 : mode == Mode::Dvr ? 1 : 2;
  cl::Kernel kernel = first_.kernel("multidev/composite_parts.cl", "composite_parts",
                                    "-D MODE=" + std::to_string(modeIndex));
  cl_uint packed = 0;
  for (size_t k = 0; k < order.size(); ++k) packed |= cl_uint(order[k]) << (4 * k);
  kernel.setArg(0, own);
  kernel.setArg(1, others_);
  kernel.setArg(2, rgba_);
  kernel.setArg(3, cl_int(width));
  kernel.setArg(4, cl_int(height));
  kernel.setArg(5, cl_int(links_.size()));
  kernel.setArg(6, packed);
  kernel.setArg(7, cl_float4{{background.x, background.y, background.z, earlyTermination}});
  const bool gpu = first_.info.isGpu;
  cl::NDRange local = gpu ? cl::NDRange(64, 4) : cl::NullRange;
  size_t gx = size_t(width), gy = size_t(band.rows);
  if (gpu) {
    gx = (gx + 63) / 64 * 64;
    gy = (gy + 3) / 4 * 4;
  }
  transfers_.enqueueNDRangeKernel(kernel, cl::NDRange(0, size_t(band.first)), cl::NDRange(gx, gy),
                                  local, &before);
  transfers_.enqueueReadBuffer(rgba_, CL_FALSE, size_t(width) * size_t(band.first) * 4,
                               bandPixels * 4, out + size_t(width) * size_t(band.first) * 4);
  transfers_.flush();
}

void DeviceCompositor::finish() { transfers_.finish(); }

}  // namespace voxray
