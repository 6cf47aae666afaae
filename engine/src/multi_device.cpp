#include "voxray/engine/multi_device.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "device_frame.h"
#include "empty_space.h"
#include "multi_device_composite.h"
#include "voxray/engine/cl_context.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

std::string mib(size_t bytes) {
  double m = double(bytes) / double(1 << 20);
  char text[32];
  std::snprintf(text, sizeof(text), m < 10 ? "%.2f MiB" : "%.0f MiB", m);
  return text;
}

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
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
    size_t capacity = 0;  // pixels
    PartImage image;      // points into the mapped host buffers
    cl::Event done;
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
    void reserve(size_t pixels) {
      if (pixels <= capacity) return;
      unmap();
      const size_t colourBytes = pixels * sizeof(cl_float4), orderBytes = pixels * sizeof(cl_float);
      colour = cl::Buffer(cl.context, CL_MEM_WRITE_ONLY, colourBytes);
      order = cl::Buffer(cl.context, CL_MEM_WRITE_ONLY, orderBytes);
      hostColour = cl::Buffer(cl.context, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR, colourBytes);
      hostOrder = cl::Buffer(cl.context, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR, orderBytes);
      image.colour = static_cast<const float*>(
          cl.queue.enqueueMapBuffer(hostColour, CL_TRUE, CL_MAP_READ, 0, colourBytes));
      image.order = static_cast<const float*>(
          cl.queue.enqueueMapBuffer(hostOrder, CL_TRUE, CL_MAP_READ, 0, orderBytes));
      capacity = pixels;
    }
  };
  const Volume& volume;
  MultiDeviceOptions opts;
  std::vector<std::unique_ptr<Part>> parts;

  Impl(const Volume& v, const MultiDeviceOptions& o) : volume(v), opts(o) {}
  void upload(Part& part, int index);
  void enqueue(Part& part, int index, const RenderParams& p, std::string& variant);
};

void MultiDeviceRenderer::Impl::upload(Part& part, int index) {
  const DeviceInfo& d = part.cl.info;
  const glm::ivec3 n = volume.dims;
  const PartRange& r = part.range;
  const size_t sliceBytes = size_t(n.x) * size_t(n.y) * sizeof(int16_t);
  const int slices = r.storedEnd - r.storedFirst;
  const size_t bytes = size_t(slices) * sliceBytes;
  size_t limit = d.maxAllocBytes;
  std::string limitText = "its largest allocation (" + mib(limit) + ")";
  if (opts.budgetBytes > 0 && opts.budgetBytes < limit) {
    limit = opts.budgetBytes;
    limitText = "the budget per device (" + mib(limit) + ")";
  }
  const std::string what = "device " + std::to_string(index + 1) + " of " +
                           std::to_string(parts.size()) + " (" + d.name + ") holds slices " +
                           std::to_string(r.storedFirst) + " to " +
                           std::to_string(r.storedEnd - 1) + " of " + std::to_string(n.z) +
                           " (its range and apron, " + mib(bytes) + ")";
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
  auto* first = const_cast<int16_t*>(volume.voxels.data()) + size_t(r.storedFirst) * n.x * n.y;
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
  if (opts.emptySpaceSkipping) part.space.upload(part.cl, volume);
}

MultiDeviceRenderer::MultiDeviceRenderer(const std::vector<ClContext*>& contexts,
                                         const Volume& volume, const MultiDeviceOptions& options)
    : impl_(std::make_unique<Impl>(volume, options)) {
  if (volume.voxelCount() == 0 || volume.voxels.size() != volume.voxelCount())
    throw inputError("the volume is empty or its voxel count does not match its dimensions");
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

int MultiDeviceRenderer::partCount() const { return int(impl_->parts.size()); }

std::vector<PartRange> MultiDeviceRenderer::ranges() const {
  std::vector<PartRange> out;
  for (const auto& p : impl_->parts) out.push_back(p->range);
  return out;
}

void MultiDeviceRenderer::Impl::enqueue(Part& part, int index, const RenderParams& p,
                                        std::string& variant) {
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
  const std::string options = "-cl-fast-relaxed-math " + switchOptions(sw, false);
  if (index == 0) variant = options;
  const size_t pixels = size_t(p.width) * size_t(p.height);
  cl::Kernel kernel = part.cl.kernel("multidev/raycast_part.cl", "raycast_part", options);
  clCall([&] {
    part.reserve(pixels);
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
    kernel.setArg(arg++, part.colour);
    kernel.setArg(arg++, part.order);
    kernel.setArg(arg++, part.space.leap());
    kernel.setArg(arg++, part.space.range());
    // Planes between slices r.first - 1 and r.first (voxel centres at integers: the plane
    // z = first holds slice first's centre, whose samples are this part's).
    kernel.setArg(arg++, cl_float2{{float(r.first), float(r.end)}});
    kernel.setArg(arg++, cl_int2{{r.first == 0 ? 1 : 0, r.end == volume.dims.z ? 1 : 0}});
    cl::NDRange local = part.cl.info.isGpu ? cl::NDRange(16, 8) : cl::NullRange;
    size_t gx = size_t(p.width), gy = size_t(p.height);
    if (local.dimensions() == 2) {
      gx = (gx + 15) / 16 * 16;
      gy = (gy + 7) / 8 * 8;
    }
    cl::CommandQueue& q = part.cl.queue;
    q.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(gx, gy), local, nullptr, &part.done);
    q.enqueueReadBuffer(part.colour, CL_FALSE, 0, pixels * sizeof(cl_float4),
                        const_cast<float*>(part.image.colour));
    q.enqueueReadBuffer(part.order, CL_FALSE, 0, pixels * sizeof(cl_float),
                        const_cast<float*>(part.image.order));
    q.flush();  // start now, while the next device is set up
    return 0;
  });
}

std::vector<double> MultiDeviceRenderer::visibilityKeys(const RenderParams& p) {
  std::vector<double> keys;
  const int slices = impl_->volume.dims.z;
  for (auto& part : impl_->parts) {
    DeviceFrame& f = part->frame;
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
  std::string variant;
  std::vector<PartStats> partStats(m.parts.size());
  for (size_t k = 0; k < m.parts.size(); ++k) {
    Impl::Part& part = *m.parts[k];
    // The volume's value range, found once by the first part (a pass over the whole volume).
    if (k > 0 && !part.frame.valueRange) part.frame.valueRange = m.parts[0]->frame.valueRange;
    try {
      m.enqueue(part, int(k), p, variant);
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
    try {
      cl_ulong t0 = part.done.getProfilingInfo<CL_PROFILING_COMMAND_START>();
      cl_ulong t1 = part.done.getProfilingInfo<CL_PROFILING_COMMAND_END>();
      s.kernelMs = double(t1 - t0) * 1e-6;
    } catch (const cl::Error&) {
      s.kernelMs = 0.0;  // some drivers do not profile
    }
  }
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
