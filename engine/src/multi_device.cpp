#include "voxray/engine/multi_device.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "device_frame.h"
#include "elapsed_ms.h"
#include "empty_space.h"
#include "mib_text.h"
#include "multi_device_composite.h"
#include "multi_device_gpu_composite.h"
#include "streamed_cells.h"
#include "voxray/engine/cl_context.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

using Clock = std::chrono::steady_clock;

// From the first of EVENTS' start to the last one's end (a part's kernel, per band, on one
// device's clock; bands may overlap); 0 where the driver does not profile.
double kernelMs(const std::vector<cl::Event>& events) {
  if (events.empty()) return 0.0;
  cl_ulong first = ~cl_ulong(0), last = 0;
  try {
    for (const cl::Event& e : events) {
      first = std::min(first, e.getProfilingInfo<CL_PROFILING_COMMAND_START>());
      last = std::max(last, e.getProfilingInfo<CL_PROFILING_COMMAND_END>());
    }
  } catch (const cl::Error&) {
    return 0.0;
  }
  return last > first ? double(last - first) * 1e-6 : 0.0;
}

}  // namespace

std::vector<PartRange> planParts(int dimZ, const std::vector<double>& weights, int apron) {
  const int n = int(weights.size());
  if (n == 0) throw inputError("a frame over several devices needs at least one device");
  if (n > dimZ)
    throw inputError("the volume has " + std::to_string(dimZ) + " slices, fewer than the " +
                     std::to_string(n) + " devices to split it over: use at most " +
                     std::to_string(dimZ) + " devices");
  for (double w : weights)
    if (!(w > 0.0)) throw inputError("every device's share of the volume must be positive");
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  std::vector<PartRange> out(static_cast<size_t>(n));
  double sum = 0.0;
  int first = 0;
  for (int k = 0; k < n; ++k) {
    sum += weights[size_t(k)];
    // Rounded cumulative shares; at least one slice each, and one left for each after.
    int end = k + 1 == n ? dimZ : int(std::lround(dimZ * sum / total));
    end = std::clamp(end, first + 1, dimZ - (n - 1 - k));
    PartRange& r = out[size_t(k)];
    r.first = first;
    r.end = end;
    r.storedFirst = std::max(first - apron, 0);
    r.storedEnd = std::min(end + apron, dimZ);
    first = end;
  }
  return out;
}

struct MultiDeviceRenderer::Impl {
  struct Part {
    ContextImpl& cl;
    PartRange range;
    DeviceFrame frame;  // the setup, parameters and table; its own volume upload is unused
    cl::Buffer slabBuffer;
    cl::Image3D slabImage;
    EmptySpace space;
    cl::Buffer colour, order;  // on the device
    // Their copies on the host, in pinned memory (CL_MEM_ALLOC_HOST_PTR, mapped once): a GPU
    // copies into it at the bus's speed, where pageable memory goes through a staging copy.
    cl::Buffer hostColour, hostOrder;
    size_t capacity = 0, hostCapacity = 0;  // pixels
    PartImage image;                        // points into the mapped host buffers
    std::vector<cl::Event> done;            // the kernel, per band of rows
    cl::CommandQueue secondQueue;           // every other band's (made for banded frames)
    bool second() const { return secondQueue() != nullptr; }
    Part(ContextImpl& c, const Volume& v, PartRange r, VolumeStorage s)
        : cl(c), range(r), frame(c, v, s) {}
    ~Part() { unmap(); }
    void unmap() {
      try {
        if (image.colour)
          cl.queue.enqueueUnmapMemObject(hostColour, const_cast<float*>(image.colour));
        if (image.order) cl.queue.enqueueUnmapMemObject(hostOrder, const_cast<float*>(image.order));
        cl.queue.finish();
      } catch (const cl::Error&) {
        // the buffers go with the context; nothing else to do while tearing down
      }
      image = PartImage{};
    }
    // HOST: the host copies too (the host composite, renderParts).
    void reserve(size_t pixels, bool host) {
      const size_t colourBytes = pixels * sizeof(cl_float4), orderBytes = pixels * sizeof(cl_float);
      if (pixels > capacity) {
        colour = cl::Buffer(cl.context, CL_MEM_READ_WRITE, colourBytes);
        order = cl::Buffer(cl.context, CL_MEM_READ_WRITE, orderBytes);
        capacity = pixels;
      }
      if (!host || pixels <= hostCapacity) return;
      unmap();
      hostColour = cl::Buffer(cl.context, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR, colourBytes);
      hostOrder = cl::Buffer(cl.context, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR, orderBytes);
      image.colour = static_cast<const float*>(
          cl.queue.enqueueMapBuffer(hostColour, CL_TRUE, CL_MAP_READ, 0, colourBytes));
      image.order = static_cast<const float*>(
          cl.queue.enqueueMapBuffer(hostOrder, CL_TRUE, CL_MAP_READ, 0, orderBytes));
      hostCapacity = pixels;
    }
  };
  const Volume& volume;
  MultiDeviceOptions opts;
  std::vector<std::unique_ptr<Part>> parts;
  std::unique_ptr<DeviceCompositor> compositor;  // made at the first device-composited frame
  bool balancing = false;                        // opts.balance, and each holds the volume
  std::vector<double> lastKernelMs;              // per part, the last frame's

  Impl(const Volume& v, const MultiDeviceOptions& o) : volume(v), opts(o) {}
  void upload(Part& part, int index);
  // opts.balance: moves the planes between the parts so that the last frame's kernel times,
  // spread evenly over each part's slices, would have been equal.
  void rebalance();
  // PART's kernel over BANDS of rows (part.done: one event each). HALF: into the compositor's
  // half-float image of the part, nothing read back; else float colour and order, read back
  // into the host copies.
  void enqueue(Part& part, int index, const RenderParams& p, std::string& variant,
               const std::vector<FrameBand>& bands, bool half);
  // The frame with the composite on the first device (DeviceCompositor) into OUT.
  // ORDER: the parts front to back (visibilityKeys). STATS: one per part.
  void renderOnDevice(const RenderParams& p, const std::vector<int>& order, Image& out,
                      std::vector<PartStats>& stats, std::string& variant, Clock::time_point start,
                      double& compositeMs);
};

void MultiDeviceRenderer::Impl::upload(Part& part, int index) {
  const DeviceInfo& d = part.cl.info;
  const glm::ivec3 n = volume.dims;
  const PartRange& r = part.range;
  const size_t sliceBytes = size_t(n.x) * size_t(n.y) * sizeof(int16_t);
  const int slices = r.storedEnd - r.storedFirst;
  const size_t bytes = size_t(slices) * sliceBytes;
  size_t limit = d.maxAllocBytes;
  std::string limitText = "its largest allocation (" + mibText(limit) + ")";
  if (opts.budgetBytes > 0 && opts.budgetBytes < limit) {
    limit = opts.budgetBytes;
    limitText = "the budget per device (" + mibText(limit) + ")";
  }
  const std::string what = "device " + std::to_string(index + 1) + " of " +
                           std::to_string(parts.size()) + " (" + d.name + ") holds slices " +
                           std::to_string(r.storedFirst) + " to " +
                           std::to_string(r.storedEnd - 1) + " of " + std::to_string(n.z) +
                           " (its range and apron, " + mibText(bytes) + ")";
  if (bytes > limit)
    throw deviceError(what + ", more than " + limitText +
                      ": split over more devices (--split), or crop or downsample the volume");
  bool image = part.frame.storage == VolumeStorage::Image3d;
  if (image && (size_t(n.x) > d.maxImage3d[0] || size_t(n.y) > d.maxImage3d[1] ||
                size_t(slices) > d.maxImage3d[2]))
    throw deviceError(what + ", more than its largest 3D image (" +
                      std::to_string(d.maxImage3d[0]) + "x" + std::to_string(d.maxImage3d[1]) +
                      "x" + std::to_string(d.maxImage3d[2]) +
                      "): render with --storage buffer or split over more devices");
  // The stored slices: in the whole volume, or in the rank's slab (opts.slab).
  const Volume& held = opts.slab ? *opts.slab : volume;
  const int heldFirst = opts.slab ? opts.slabFirst : 0;
  auto* first = const_cast<int16_t*>(held.voxels.data()) +
                size_t(r.storedFirst - heldFirst) * size_t(n.x) * size_t(n.y);
  try {
    clCall([&] {
      if (image) {
        cl::ImageFormat format(CL_R, CL_SNORM_INT16);  // as DeviceVolume: the kernel scales back
        part.slabImage = cl::Image3D(part.cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                     format, size_t(n.x), size_t(n.y), size_t(slices), 0, 0, first);
      } else {
        // A CPU device reads the volume where it is (DeviceVolume does the same).
        cl_mem_flags where = d.isGpu ? CL_MEM_COPY_HOST_PTR : CL_MEM_USE_HOST_PTR;
        part.slabBuffer = cl::Buffer(part.cl.context, CL_MEM_READ_ONLY | where, bytes, first);
      }
      part.frame.paramsBuffer =
          cl::Buffer(part.cl.context, CL_MEM_READ_ONLY, sizeof(RaycastParams));
      return 0;
    });
  } catch (const Error& e) {
    throw deviceError(what + ": " + e.what());
  }
  if (opts.emptySpaceSkipping) {
    if (opts.slab)
      part.space.upload(part.cl,
                        slabMacroCells(*opts.slab, opts.slabFirst, n.z, opts.valueRange->min));
    else
      part.space.upload(part.cl, volume);
  }
}

MultiDeviceRenderer::MultiDeviceRenderer(const std::vector<ClContext*>& contexts,
                                         const Volume& volume, const MultiDeviceOptions& options)
    : impl_(std::make_unique<Impl>(volume, options)) {
  if (options.slab) {
    const Volume& slab = *options.slab;
    if (slab.voxels.size() != slab.voxelCount() || slab.dims.x != volume.dims.x ||
        slab.dims.y != volume.dims.y || options.slabFirst < 0 ||
        options.slabFirst + slab.dims.z > volume.dims.z || volume.voxelCount() == 0)
      throw inputError("the slab (" + std::to_string(slab.dims.z) + " slices from " +
                       std::to_string(options.slabFirst) + ") does not fit the volume's " +
                       std::to_string(volume.dims.x) + "x" + std::to_string(volume.dims.y) + "x" +
                       std::to_string(volume.dims.z) + " voxels");
    if (!options.valueRange) throw inputError("a slab renderer needs the whole volume's range");
    for (const PartRange& r : options.ranges)
      if (r.storedFirst < options.slabFirst || r.storedEnd > options.slabFirst + slab.dims.z)
        throw inputError("the slab holds slices " + std::to_string(options.slabFirst) + " to " +
                         std::to_string(options.slabFirst + slab.dims.z - 1) +
                         ", not the stored slices " + std::to_string(r.storedFirst) + " to " +
                         std::to_string(r.storedEnd - 1) + " of its range");
    if (options.ranges.empty()) throw inputError("a slab renderer needs its ranges");
  } else if (volume.voxelCount() == 0 || volume.voxels.size() != volume.voxelCount()) {
    throw inputError("the volume is empty or its voxel count does not match its dimensions");
  }
  if (options.apron < 2)
    throw inputError("the apron must be at least 2 slices (the gradients' stencil)");
  // Shares by the memory each device may use: equal devices get equal ranges.
  std::vector<double> weights;
  for (ClContext* c : contexts) {
    double mem = double(c->device().globalMemBytes);
    if (options.budgetBytes > 0) mem = std::min(mem, double(options.budgetBytes));
    weights.push_back(std::max(mem, 1.0));
  }
  std::vector<PartRange> ranges = options.ranges;
  if (ranges.empty()) {
    ranges = planParts(volume.dims.z, weights, options.apron);
  } else if (ranges.size() != contexts.size()) {
    throw inputError("give one range per device: " + std::to_string(ranges.size()) +
                     " ranges for " + std::to_string(contexts.size()) + " devices");
  } else {
    for (const PartRange& r : ranges)
      if (r.first < 0 || r.end > volume.dims.z || r.first >= r.end ||
          r.storedFirst > std::max(r.first - options.apron, 0) ||
          r.storedEnd < std::min(r.end + options.apron, volume.dims.z))
        throw inputError("the range of slices " + std::to_string(r.first) + " to " +
                         std::to_string(r.end - 1) + " (held " + std::to_string(r.storedFirst) +
                         " to " + std::to_string(r.storedEnd - 1) + ") does not fit the " +
                         std::to_string(volume.dims.z) + " slices with an apron of " +
                         std::to_string(options.apron));
  }
  if (options.balance && options.ranges.empty() && contexts.size() > 1) {
    // Each holds the whole volume where every device can (its largest allocation, the
    // budget, a 3D image's depth); else the ranges stay planParts'.
    const glm::ivec3 n = volume.dims;
    const size_t bytes = size_t(n.x) * size_t(n.y) * size_t(n.z) * sizeof(int16_t);
    bool fits = true;
    for (ClContext* c : contexts) {
      const DeviceInfo& d = c->device();
      size_t limit = d.maxAllocBytes;
      if (options.budgetBytes > 0) limit = std::min(limit, options.budgetBytes);
      const bool image = options.storage == VolumeStorage::Image3d ||
                         (options.storage == VolumeStorage::Auto && d.isGpu && d.imageSupport);
      fits = fits && bytes <= limit && (!image || size_t(n.z) <= d.maxImage3d[2]);
    }
    if (fits) {
      for (PartRange& r : ranges) {
        r.storedFirst = 0;
        r.storedEnd = n.z;
      }
      impl_->balancing = true;
    }
  }
  for (size_t k = 0; k < contexts.size(); ++k) {
    ContextImpl& cl = contexts[k]->impl();
    VolumeStorage s = options.storage;
    if (s == VolumeStorage::Auto)
      s = cl.info.isGpu && cl.info.imageSupport ? VolumeStorage::Image3d : VolumeStorage::Buffer;
    if (s == VolumeStorage::Image3d && !cl.info.imageSupport)
      throw deviceError(cl.info.name + " has no image support: render with the buffer storage");
    impl_->parts.push_back(std::make_unique<Impl::Part>(cl, volume, ranges[k], s));
    impl_->parts.back()->frame.valueRange = options.valueRange;
  }
  for (size_t k = 0; k < impl_->parts.size(); ++k) impl_->upload(*impl_->parts[k], int(k));
}

MultiDeviceRenderer::~MultiDeviceRenderer() = default;

void MultiDeviceRenderer::setComposite(MultiDeviceOptions::Composite where) {
  impl_->opts.composite = where;
}

int MultiDeviceRenderer::partCount() const { return int(impl_->parts.size()); }

std::vector<PartRange> MultiDeviceRenderer::ranges() const {
  std::vector<PartRange> out;
  for (const auto& p : impl_->parts) out.push_back(p->range);
  return out;
}

void MultiDeviceRenderer::Impl::enqueue(Part& part, int index, const RenderParams& p,
                                        std::string& variant, const std::vector<FrameBand>& bands,
                                        bool half) {
  DeviceFrame& f = part.frame;
  f.updateSetup(p);
  // A sample a range takes may lie up to a step beyond its plane (dvr's first and last
  // segments, iso's refinement from the sample before); its stencil reaches 2 slices
  // further. Beyond the apron it would read the clamped edge: refuse rather than show that.
  const double stepSlices = f.setup.stepMm / volume.spacingMm.z;
  if (stepSlices > double(opts.apron - 2) + 1e-6) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  "the step (%.3g mm, %.3g slices) is longer than the %d slices a frame over "
                  "several devices allows with its apron of %d",
                  f.setup.stepMm, stepSlices, opts.apron - 2, opts.apron);
    throw inputError(std::string(text) + ": render with a finer --step");
  }
  KernelFacts facts;
  facts.emptySpaceSkipping = opts.emptySpaceSkipping;
  facts.storageImage = f.storage == VolumeStorage::Image3d;
  KernelSwitches sw = kernelSwitches(p, facts);
  sw.ADAPTIVE = 0;  // segments grouped from a range's start would not be the whole ray's
  RaycastParams k = f.frameParams(p, sw);
  glm::ivec3 cells = part.space.dims();
  k.cells = {{cells.x, cells.y, cells.z, 0}};
  const std::string options =
      "-cl-fast-relaxed-math " + switchOptions(sw, false) + (half ? " -D PART_HALF=1" : "");
  if (index == 0) variant = options;
  const size_t pixels = size_t(p.width) * size_t(p.height);
  cl::Kernel kernel = part.cl.kernel("multidev/raycast_part.cl", "raycast_part", options);
  clCall([&] {
    part.reserve(pixels, !half);
    f.uploadFrame(k);
    // mip reads the cells' min/max directly (as the one-ray-per-work-item raycaster).
    if (opts.emptySpaceSkipping && p.mode != Mode::Mip)
      part.space.classify(part.cl, f.paramsBuffer, f.lutBuffer, k, p.mode, f.setup.lut, false,
                          false, false);
    cl_uint arg = 0;
    if (f.storage == VolumeStorage::Image3d)
      kernel.setArg(arg++, part.slabImage);
    else
      kernel.setArg(arg++, part.slabBuffer);
    const PartRange& r = part.range;
    kernel.setArg(arg++, cl_int2{{r.storedFirst, r.storedEnd - r.storedFirst}});
    kernel.setArg(arg++, f.paramsBuffer);
    kernel.setArg(arg++, f.lutBuffer);
    kernel.setArg(arg++, half ? compositor->partImage(size_t(index)) : part.colour);
    kernel.setArg(arg++, part.order);
    kernel.setArg(arg++, part.space.leap());
    kernel.setArg(arg++, part.space.range());
    // Planes between slices r.first - 1 and r.first (voxel centres at integers: the plane
    // z = first holds slice first's centre, whose samples are this part's).
    kernel.setArg(arg++, cl_float2{{float(r.first), float(r.end)}});
    kernel.setArg(arg++, cl_int2{{r.first == 0 ? 1 : 0, r.end == volume.dims.z ? 1 : 0}});
    cl::NDRange local = part.cl.info.isGpu ? cl::NDRange(16, 8) : cl::NullRange;
    size_t gx = size_t(p.width);
    if (local.dimensions() == 2) gx = (gx + 15) / 16 * 16;
    cl::CommandQueue& q = part.cl.queue;
    // Bands alternate between two in-order queues: a band's last work-groups run beside the
    // next band's first instead of leaving the device idle until they finish (one queue cost
    // 8 bands at 4K about a fifth of the kernel time on an H200: docs/bench/gpu-h200x2-round9.txt).
    if (bands.size() > 1 && !part.second())
      part.secondQueue =
          cl::CommandQueue(part.cl.context, part.cl.device, CL_QUEUE_PROFILING_ENABLE);
    // The second queue's bands after this frame's writes on the first (parameters, cells).
    std::vector<cl::Event> setup(1);
    if (bands.size() > 1) q.enqueueMarkerWithWaitList(nullptr, &setup[0]);
    part.done.clear();
    for (size_t i = 0; i < bands.size(); ++i) {
      const FrameBand& b = bands[i];
      // Bands other than the last are whole work-groups tall (frameBands).
      size_t gy = size_t(b.rows);
      if (local.dimensions() == 2) gy = (gy + 7) / 8 * 8;
      part.done.emplace_back();
      (i % 2 ? part.secondQueue : q)
          .enqueueNDRangeKernel(kernel, cl::NDRange(0, size_t(b.first)), cl::NDRange(gx, gy), local,
                                i % 2 ? &setup : nullptr, &part.done.back());
    }
    if (half) {
      q.flush();
      if (bands.size() > 1) part.secondQueue.flush();
      return 0;
    }
    q.enqueueReadBuffer(part.colour, CL_FALSE, 0, pixels * sizeof(cl_float4),
                        const_cast<float*>(part.image.colour));
    q.enqueueReadBuffer(part.order, CL_FALSE, 0, pixels * sizeof(cl_float),
                        const_cast<float*>(part.image.order));
    q.flush();  // start now, while the next device is set up
    return 0;
  });
}

void MultiDeviceRenderer::Impl::renderOnDevice(const RenderParams& p, const std::vector<int>& order,
                                               Image& out, std::vector<PartStats>& stats,
                                               std::string& variant, Clock::time_point start,
                                               double& compositeMs) {
  const size_t n = parts.size();
  auto fail = [&](size_t k, const Error& e) {
    if (e.kind() == Error::Kind::Input) throw e;  // the frame's, not this device's
    throw deviceError("device " + std::to_string(k + 1) + " of " + std::to_string(n) + " (" +
                      parts[k]->cl.info.name + "): " + e.what());
  };
  if (!compositor) {
    std::vector<ContextImpl*> contexts;
    for (auto& part : parts) contexts.push_back(&part->cl);
    try {
      compositor = std::make_unique<DeviceCompositor>(contexts);
    } catch (const Error& e) {
      fail(0, e);
    }
  }
  const size_t pixels = size_t(p.width) * size_t(p.height);
  const int rowStep = parts[0]->cl.info.isGpu ? 8 : 1;  // the part kernel's work-group height
  const std::vector<FrameBand> bands = frameBands(p.height, opts.bands, rowStep);
  try {
    clCall([&] {
      compositor->reserve(pixels);
      compositor->beginFrame();
      return 0;
    });
  } catch (const Error& e) {
    fail(0, e);
  }
  // The first part last: the others' bands start their way back while it is set up.
  for (size_t j = n; j-- > 0;) {
    Part& part = *parts[j];
    if (j > 0 && !part.frame.valueRange && parts[0]->frame.valueRange)
      part.frame.valueRange = parts[0]->frame.valueRange;
    try {
      enqueue(part, int(j), p, variant, bands, j > 0);
      if (j > 0)
        clCall([&] {
          for (size_t b = 0; b < bands.size(); ++b)
            compositor->readBand(j, p.width, bands[b], part.done[b]);
          return 0;
        });
    } catch (const Error& e) {
      fail(j, e);
    }
  }
  out.width = p.width;
  out.height = p.height;
  out.rgba.resize(pixels * 4);
  try {
    clCall([&] {
      for (size_t b = 0; b < bands.size(); ++b)
        compositor->compositeBand(p.mode, order, glm::vec3(p.background), float(p.earlyTermination),
                                  parts[0]->colour, parts[0]->done[b], p.width, p.height, bands[b],
                                  b, out.rgba.data());
      return 0;
    });
  } catch (const Error& e) {
    fail(0, e);
  }
  // Each part's kernels done (the others' last band is on the host by now).
  double lastReady = 0.0;
  for (size_t k = 0; k < n; ++k) {
    Part& part = *parts[k];
    try {
      clCall([&] { return cl::Event::waitForEvents(part.done); });
    } catch (const Error& e) {
      fail(k, e);
    }
    PartStats& s = stats[k];
    s.readyMs = msSince(start);
    s.device = part.cl.info.name;
    s.range = part.range;
    s.kernelMs = kernelMs(part.done);
    lastReady = std::max(lastReady, s.readyMs);
  }
  try {
    clCall([&] {
      compositor->finish();
      return 0;
    });
  } catch (const Error& e) {
    fail(0, e);
  }
  compositeMs = msSince(start) - lastReady;
}

void MultiDeviceRenderer::Impl::rebalance() {
  const size_t n = parts.size();
  if (!balancing || lastKernelMs.size() != n) return;
  double total = 0.0;
  for (double t : lastKernelMs) {
    if (!(t > 0.0)) return;  // a driver that does not profile: nothing to go by
    total += t;
  }
  // Cost per slice, constant within each part's range; the new planes cut the cumulative
  // cost into equal shares.
  const int slices = volume.dims.z;
  std::vector<int> planes;
  double sum = 0.0;
  size_t k = 0;
  for (size_t j = 1; j < n; ++j) {
    const double target = total * double(j) / double(n);
    while (k < n && sum + lastKernelMs[k] < target) sum += lastKernelMs[k++];
    const PartRange& r = parts[std::min(k, n - 1)]->range;
    const double perSlice = lastKernelMs[std::min(k, n - 1)] / double(r.end - r.first);
    planes.push_back(int(std::lround(double(r.first) + (target - sum) / perSlice)));
  }
  int first = 0;
  for (size_t j = 0; j < n; ++j) {
    PartRange& r = parts[j]->range;
    // At least one slice each, and one left for each after.
    int end = j + 1 == n ? slices : planes[j];
    end = std::clamp(end, first + 1, slices - int(n - 1 - j));
    r.first = first;
    r.end = end;
    first = end;
  }
}

std::vector<double> MultiDeviceRenderer::visibilityKeys(const RenderParams& p) {
  std::vector<double> keys;
  const int slices = impl_->volume.dims.z;
  for (auto& part : impl_->parts) {
    DeviceFrame& f = part->frame;
    // The volume's value range, found once by the first part (a pass over the whole volume).
    if (!f.valueRange) f.valueRange = impl_->parts[0]->frame.valueRange;
    f.updateSetup(p);
    const ViewGeometry& g = f.setup.view;
    const PartRange& r = part->range;
    // The planes z = first and z = end bound the part's samples (raycast_part.cl); the first
    // and last parts are open below and above.
    const double lo = r.first == 0 ? -HUGE_VAL : double(r.first);
    const double hi = r.end == slices ? HUGE_VAL : double(r.end);
    if (p.camera.projection == Projection::Orthographic) {
      const double dz = g.dirToVoxel(g.forward).z;
      keys.push_back(dz >= 0.0 ? double(r.first) : -double(r.first));
    } else {
      const double ez = g.toVoxel(g.eye).z;
      keys.push_back(std::max({lo - ez, ez - hi, 0.0}));
    }
  }
  return keys;
}

std::vector<PartImage> MultiDeviceRenderer::renderParts(const RenderParams& p,
                                                        MultiDeviceStats* stats) {
  std::vector<PartImage> images;
  renderInto(p, nullptr, stats, &images);
  return images;
}

void MultiDeviceRenderer::render(const RenderParams& p, Image& out, MultiDeviceStats* stats) {
  renderInto(p, &out, stats, nullptr);
}

void MultiDeviceRenderer::renderInto(const RenderParams& p, Image* out, MultiDeviceStats* stats,
                                     std::vector<PartImage>* partImages) {
  const auto start = Clock::now();
  if (p.lighting != Lighting::Phong)
    throw inputError(std::string("a frame over several devices is lit by phong only, not ") +
                     toString(p.lighting) + ": render it on one device");
  if (p.width <= 0 || p.height <= 0) throw inputError("the image size must be positive");
  Impl& m = *impl_;
  m.rebalance();
  std::string variant;
  std::vector<PartStats> partStats(m.parts.size());
  // The composite packs the parts' order in 4 bits each (composite_parts.cl): 8 at most.
  if (out && !partImages && m.opts.composite == MultiDeviceOptions::Composite::Device &&
      m.parts.size() <= 8) {
    std::vector<double> keys = visibilityKeys(p);
    std::vector<int> order(m.parts.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return keys[size_t(a)] < keys[size_t(b)]; });
    double compositeMs = 0.0;
    m.renderOnDevice(p, order, *out, partStats, variant, start, compositeMs);
    m.lastKernelMs.clear();
    for (const PartStats& s : partStats) m.lastKernelMs.push_back(s.kernelMs);
    if (stats) {
      stats->deviceComposite = true;
      stats->compositeMs = compositeMs;
      stats->parts = std::move(partStats);
      stats->variant = variant;
      stats->totalMs = msSince(start);
    }
    return;
  }
  const std::vector<FrameBand> whole{{0, p.height}};
  for (size_t k = 0; k < m.parts.size(); ++k) {
    Impl::Part& part = *m.parts[k];
    // The volume's value range, found once by the first part (a pass over the whole volume).
    if (k > 0 && !part.frame.valueRange) part.frame.valueRange = m.parts[0]->frame.valueRange;
    try {
      m.enqueue(part, int(k), p, variant, whole, false);
    } catch (const Error& e) {
      if (e.kind() == Error::Kind::Input) throw;  // the frame's, not this device's
      throw deviceError("device " + std::to_string(k + 1) + " of " +
                        std::to_string(m.parts.size()) + " (" + part.cl.info.name +
                        "): " + e.what());
    }
  }
  for (size_t k = 0; k < m.parts.size(); ++k) {
    Impl::Part& part = *m.parts[k];
    try {
      clCall([&] { return part.cl.queue.finish(); });
    } catch (const Error& e) {
      throw deviceError("device " + std::to_string(k + 1) + " of " +
                        std::to_string(m.parts.size()) + " (" + part.cl.info.name +
                        "): " + e.what());
    }
    PartStats& s = partStats[k];
    s.readyMs = msSince(start);
    s.device = part.cl.info.name;
    s.range = part.range;
    s.kernelMs = kernelMs(part.done);
  }
  m.lastKernelMs.clear();
  for (const PartStats& s : partStats) m.lastKernelMs.push_back(s.kernelMs);
  const auto composite = Clock::now();
  if (out) {
    std::vector<const PartImage*> images;
    for (const auto& part : m.parts) images.push_back(&part->image);
    compositeParts(p.mode, images, p.width, p.height, glm::vec3(p.background),
                   float(p.earlyTermination), *out);
  }
  if (partImages) {
    partImages->clear();
    for (const auto& part : m.parts) partImages->push_back(part->image);
  }
  if (stats) {
    stats->compositeMs = msSince(composite);
    stats->parts = std::move(partStats);
    stats->variant = variant;
    stats->totalMs = msSince(start);
  }
}

std::vector<std::unique_ptr<ClContext>> splitDevice(const std::string& selector, int parts) {
  if (parts < 1) throw inputError("--split: the number of parts must be at least 1");
  std::vector<std::unique_ptr<ClContext>> out;
  if (parts > 1) out = ClContext::subDevices(selector, parts);
  if (out.empty())
    for (int k = 0; k < parts; ++k) out.push_back(std::make_unique<ClContext>(selector));
  return out;
}

}  // namespace voxray
