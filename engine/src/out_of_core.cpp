#include "voxray/engine/out_of_core.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "macro_cells.h"
#include "mib_text.h"
#include "out_of_core_impl.h"
#include "rgba8.h"
#include "streamed_cells.h"
#include "voxray/io/error.h"
#include "voxray/io/parallel.h"
#include "voxray/io/volume.h"

namespace voxray {

using ooc::Clock;

namespace {

// The device bytes EmptySpace holds for CELLS cells: min/max, occupancy, distances and level,
// scratch.
size_t cellBytes(const glm::ivec3& cells) {
  return size_t(cells.x) * size_t(cells.y) * size_t(cells.z) * 8;
}

// The build options of a part's (and the coarse level's) raycast for P.
std::string partOptions(const RenderParams& p, bool emptySpaceSkipping, VolumeStorage storage) {
  KernelFacts facts;
  facts.emptySpaceSkipping = emptySpaceSkipping;
  facts.storageImage = storage == VolumeStorage::Image3d;
  KernelSwitches sw = kernelSwitches(p, facts);
  sw.ADAPTIVE = 0;  // segments grouped from a part's start would not be the whole ray's
  return "-cl-fast-relaxed-math " + switchOptions(sw, false);
}

VolumeStorage resolved(const DeviceInfo& info, VolumeStorage s) {
  if (s == VolumeStorage::Auto)
    return info.isGpu && info.imageSupport ? VolumeStorage::Image3d : VolumeStorage::Buffer;
  return s;
}

}  // namespace

void OutOfCoreRenderer::prebuild(ClContext& context, const RenderParams& p,
                                 const OutOfCoreOptions& o) {
  const VolumeStorage s = resolved(context.device(), o.storage);
  if (s == VolumeStorage::Image3d && !context.device().imageSupport) return;  // the ctor says
  context.prebuild("multidev/raycast_part.cl", partOptions(p, o.emptySpaceSkipping, s));
  context.prebuild("multidev/accumulate_part.cl", "");
  if (o.emptySpaceSkipping && p.mode != Mode::Mip) context.prebuild("empty_space/classify.cl", "");
}

void OutOfCoreRenderer::Impl::keys(std::vector<Item>& items, const RenderParams& p) {
  const ViewGeometry& g = full.setup.view;
  for (Item& it : items) {
    // As MultiDeviceRenderer::visibilityKeys: slabs of z, ordered along the view's z.
    const double lo = it.first == 0 ? -HUGE_VAL : double(it.first);
    const double hi = it.end == geom.dims.z ? HUGE_VAL : double(it.end);
    if (p.camera.projection == Projection::Orthographic) {
      const double dz = g.dirToVoxel(g.forward).z;
      it.key = dz >= 0.0 ? double(it.first) : -double(it.first);
    } else {
      const double ez = g.toVoxel(g.eye).z;
      it.key = std::max({lo - ez, ez - hi, 0.0});
    }
  }
  std::stable_sort(items.begin(), items.end(),
                   [](const Item& a, const Item& b) { return a.key < b.key; });
}

void OutOfCoreRenderer::Impl::setUp(DeviceFrame& f, EmptySpace& space, const RenderParams& p,
                                    RaycastParams& k, std::string& options, bool classify) {
  KernelFacts facts;
  facts.emptySpaceSkipping = o.emptySpaceSkipping;
  facts.storageImage = storage == VolumeStorage::Image3d;
  KernelSwitches sw = kernelSwitches(p, facts);
  sw.ADAPTIVE = 0;  // segments grouped from a part's start would not be the whole ray's
  k = f.frameParams(p, sw);
  const glm::ivec3 cells = space.dims();
  k.cells = {{cells.x, cells.y, cells.z, 0}};
  options = "-cl-fast-relaxed-math " + switchOptions(sw, false);
  clCall([&] {
    f.uploadFrame(k);
    if (classify && o.emptySpaceSkipping && p.mode != Mode::Mip)
      space.classify(cl, f.paramsBuffer, f.lutBuffer, k, p.mode, f.setup.lut, false, false, false);
    return 0;
  });
}

void OutOfCoreRenderer::Impl::launch(const Item& item, const RenderParams& p) {
  const bool isCoarse = item.part < 0;
  DeviceFrame& f = isCoarse ? *coarseFrame : full;
  EmptySpace& space = isCoarse ? coarseSpace : fullSpace;
  const size_t pixels = size_t(p.width) * size_t(p.height);
  const std::string options = partOptions(p, o.emptySpaceSkipping, storage);
  cl::Kernel kernel = cl.kernel("multidev/raycast_part.cl", "raycast_part", options);
  // The planes in the level's own voxel coordinates: the full volume's slice centres z =
  // first and z = end, through LPS, along the coarse level's k axis.
  cl_float2 bounds{{float(item.first), float(item.end)}};
  cl_int2 stored{{0, coarse->dims.z}};
  if (isCoarse) {
    const glm::dvec3 k = coarse->direction[2];
    auto toCoarse = [&](double z) {
      const glm::dvec3 at = geom.originMm + geom.direction[2] * (z * geom.spacingMm.z);
      return float(glm::dot(at - coarse->originMm, k) / coarse->spacingMm.z);
    };
    bounds = {{toCoarse(item.first), toCoarse(item.end)}};
  } else {
    const PartRange& r = parts[size_t(item.part)].range;
    stored = {{r.storedFirst, r.storedEnd - r.storedFirst}};
  }
  clCall([&] {  // the image buffers: draw() made them for the frame's size
    cl_uint arg = 0;
    if (storage == VolumeStorage::Image3d)
      kernel.setArg(arg++, isCoarse ? coarseImage : parts[size_t(item.part)].image);
    else
      kernel.setArg(arg++, isCoarse ? coarseBuffer : parts[size_t(item.part)].buffer);
    kernel.setArg(arg++, stored);
    kernel.setArg(arg++, f.paramsBuffer);
    kernel.setArg(arg++, f.lutBuffer);
    kernel.setArg(arg++, colour);
    kernel.setArg(arg++, order);
    kernel.setArg(arg++, space.leap());
    kernel.setArg(arg++, space.range());
    kernel.setArg(arg++, bounds);
    kernel.setArg(arg++, cl_int2{{item.first == 0 ? 1 : 0, item.end == geom.dims.z ? 1 : 0}});
    cl::NDRange local = cl.info.isGpu ? cl::NDRange(16, 8) : cl::NullRange;
    size_t gx = size_t(p.width), gy = size_t(p.height);
    if (local.dimensions() == 2) {
      gx = (gx + 15) / 16 * 16;
      gy = (gy + 7) / 8 * 8;
    }
    // A part just copied through the pinned ring: its kernel waits for the copy (on the
    // transfer queue), the launches after it wait in order.
    std::vector<cl::Event> wait;
    Part* part = isCoarse ? nullptr : &parts[size_t(item.part)];
    if (part && part->ready()) wait.push_back(part->ready);
    cl::Event ran, added;
    cl.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(gx, gy), local,
                                  wait.empty() ? nullptr : &wait, &ran);
    if (part) {
      part->ready = cl::Event();
      part->lastUse = ran;
    }
    kernelEvents.push_back(ran);
    // Into the composite on the device, front to back (the items come in the order the rays
    // meet them): no part image crosses the bus, and the next part's slices are read and
    // uploaded while the queue runs (it is in order: the next launch waits for this one).
    cl::Kernel add = cl.kernel("multidev/accumulate_part.cl", "accumulate_part", "");
    const cl_int mode = p.mode == Mode::Iso ? 0 : p.mode == Mode::Dvr ? 1 : 2;
    add.setArg(0, colour);
    add.setArg(1, accBuffer);
    add.setArg(2, mode);
    add.setArg(3, cl_float(p.earlyTermination));
    add.setArg(4, cl_int(pixels));
    cl.queue.enqueueNDRangeKernel(add, cl::NullRange, cl::NDRange((pixels + 63) / 64 * 64),
                                  cl::NullRange, nullptr, &added);
    kernelEvents.push_back(added);
    cl.queue.flush();
    return 0;
  });
}

OutOfCoreRenderer::OutOfCoreRenderer(ClContext& context, SlabSource& source,
                                     const OutOfCoreOptions& options) {
  const auto start = Clock::now();
  ContextImpl& cl = context.impl();
  if (options.apron < 2)
    throw inputError("the apron must be at least 2 slices (the gradients' stencil)");
  const VolumeStorage s = resolved(cl.info, options.storage);
  if (s == VolumeStorage::Image3d && !cl.info.imageSupport)
    throw deviceError(cl.info.name + " has no image support: render with the buffer storage");
  const Volume& g = source.geometry();
  if (g.voxelCount() == 0) throw inputError("the volume is empty");
  // A source whose coarse level takes a pass over the volume shows its quick level first
  // (slab_source.h); the budget is planned with the coarse level's bytes all the same, so the
  // parts are the same whichever is on the device.
  const Volume* quick = source.quickLevel();
  if (!quick) source.coarse();  // made (or read) before Impl binds it
  impl_ = std::make_unique<Impl>(cl, source, options, s, quick);
  Impl& m = *impl_;
  const int apron = options.apron;
  const size_t sliceBytes = m.sliceBytes();
  const size_t budget = options.budgetBytes ? options.budgetBytes : cl.info.maxAllocBytes;
  const glm::ivec3 cells = (g.dims + (kCellSize - 1)) / kCellSize;
  const glm::ivec3 coarseDims = quick ? source.coarseDims() : m.coarse->dims;
  const glm::ivec3 coarseCells = (coarseDims + (kCellSize - 1)) / kCellSize;
  m.fixedBytes = size_t(coarseDims.x) * size_t(coarseDims.y) * size_t(coarseDims.z) * 2 +
                 (options.emptySpaceSkipping ? cellBytes(cells) + cellBytes(coarseCells) : 0);
  m.partBudget = budget > m.fixedBytes ? budget - m.fixedBytes : 0;
  const int minSlices = std::min(g.dims.z, 1 + 2 * apron);
  const size_t budgetSlices = m.partBudget / sliceBytes;
  auto tooSmall = [&](size_t slices) {
    throw inputError(
        "the memory budget of " + mibText(budget) + " leaves " + mibText(m.partBudget) +
        " for the volume's slices after its coarse level and empty-space cells (" +
        mibText(m.fixedBytes) + "), less than one part of " + std::to_string(slices) +
        " slices of " + mibText(sliceBytes) + " each needs (" + mibText(slices * sliceBytes) +
        ": its own slices and an apron of " + std::to_string(apron) +
        " on either side): raise --memory-budget to at least " +
        std::to_string((m.fixedBytes + slices * sliceBytes + (1 << 20) - 1) >> 20) + " MiB");
  };
  if (budgetSlices < size_t(minSlices)) tooSmall(size_t(minSlices));
  int owned = options.partSlices;
  if (owned <= 0) {
    // About 8 parts in the budget: a frame then uploads close to the volume less the budget
    // (n - k + 1 of n parts); thinner parts spend more of their bytes on aprons.
    const int b = int(std::min<size_t>(budgetSlices, size_t(g.dims.z) + 2 * apron));
    owned = std::max(b / 8 - 2 * apron, std::min(b - 2 * apron, 4 * apron));
    const int chunk = source.preferredSlices();
    if (chunk > 0 && owned > chunk) owned = owned / chunk * chunk;  // reads chunk-aligned
  }
  owned = std::clamp(owned, 1, g.dims.z);
  for (int first = 0; first < g.dims.z; first += owned) {
    Impl::Part p;
    p.range.first = first;
    p.range.end = std::min(first + owned, g.dims.z);
    p.range.storedFirst = std::max(first - apron, 0);
    p.range.storedEnd = std::min(p.range.end + apron, g.dims.z);
    p.bytes = size_t(p.range.storedEnd - p.range.storedFirst) * sliceBytes;
    if (p.bytes > m.partBudget) tooSmall(size_t(p.range.storedEnd - p.range.storedFirst));
    m.parts.push_back(std::move(p));
  }
  // No pass over the source (out_of_core.h): an in-memory source's cells and range are made in
  // place; a streamed source's cells start conservative and its range as stated or coarse.
  const int rows = cells.z;
  m.rowKnown.assign(size_t(rows), 0);
  MacroCells mc;
  if (source.whole()) {
    mc = computeMacroCells(*source.whole());
    for (size_t c = 0; c + 1 < mc.minMax.size(); c += 2) {
      m.knownLo = std::min<int>(m.knownLo, mc.minMax[c]);
      m.knownHi = std::max<int>(m.knownHi, mc.minMax[c + 1]);
    }
    m.rowKnown.assign(size_t(rows), 1);
    m.rowsKnown = rows;
  } else {
    // The conservative cells wait for the first frame that draws a part: a preview from the
    // coarse level needs none (67 M of them for 8 GiB took 0.42 s of a 2.6 s first image).
    m.cellsPending = options.emptySpaceSkipping;
    const std::optional<ValueRange> stated = source.statedRange();
    m.hintStated = stated.has_value();
    m.hint = stated ? *stated : storedRange(*m.coarse);
  }
  m.used = m.currentRange();
  m.full.valueRange = m.used;
  try {
    clCall([&] {
      m.full.paramsBuffer = cl::Buffer(cl.context, CL_MEM_READ_ONLY, sizeof(RaycastParams));
      return 0;
    });
    if (options.emptySpaceSkipping && !m.cellsPending) m.fullSpace.upload(cl, std::move(mc));
  } catch (const Error& e) {
    throw deviceError(cl.info.name +
                      ": the empty-space cells could not be put on the device: " + e.what());
  }
  m.uploadCoarse();
  m.openMs = msSince(start);
}

void OutOfCoreRenderer::Impl::uploadCoarse() {
  coarseFrame = std::make_unique<DeviceFrame>(cl, *coarse, storage);
  coarseFrame->valueRange = used;  // the coarse level's colours are the full volume's
  try {
    clCall([&] {
      coarseFrame->paramsBuffer = cl::Buffer(cl.context, CL_MEM_READ_ONLY, sizeof(RaycastParams));
      auto* ptr = const_cast<int16_t*>(coarse->voxels.data());
      const glm::ivec3 d = coarse->dims;
      if (storage == VolumeStorage::Image3d)
        coarseImage = cl::Image3D(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                  cl::ImageFormat(CL_R, CL_SNORM_INT16), size_t(d.x), size_t(d.y),
                                  size_t(d.z), 0, 0, ptr);
      else
        coarseBuffer = cl::Buffer(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                  coarse->byteSize(), ptr);
      return 0;
    });
    if (o.emptySpaceSkipping) {
      coarseSpace = EmptySpace();
      coarseSpace.upload(cl, *coarse);
    }
  } catch (const Error& e) {
    throw deviceError(cl.info.name + ": the coarse level (" + mibText(coarse->byteSize()) +
                      ") and its empty-space cells could not be put on the device: " + e.what());
  }
}

void OutOfCoreRenderer::Impl::makeConservativeCells() {
  MacroCells mc;
  mc.dims = (geom.dims + (kCellSize - 1)) / kCellSize;
  mc.minMax.resize(size_t(mc.dims.x) * size_t(mc.dims.y) * size_t(mc.dims.z) * 2);
  for (size_t c = 0; c < mc.minMax.size(); c += 2) {
    mc.minMax[c] = INT16_MIN;
    mc.minMax[c + 1] = INT16_MAX;
  }
  try {
    fullSpace.upload(cl, std::move(mc));
  } catch (const Error& e) {
    throw deviceError(cl.info.name +
                      ": the empty-space cells could not be put on the device: " + e.what());
  }
  cellsPending = false;
}

void OutOfCoreRenderer::Impl::replaceQuick() {
  const Volume& made = src.coarse();
  // The last launch on the quick level is done before its buffers go.
  clCall([&] { return cl.queue.finish(); });
  coarse = &made;
  quick = false;
  uploadCoarse();
  // The pass that made it found the value range (a raw file's): the frames' range from now.
  if (!hintStated) {
    if (const std::optional<ValueRange> stated = src.statedRange()) {
      hint = *stated;
      hintStated = true;
    }
  }
}

OutOfCoreRenderer::~OutOfCoreRenderer() = default;

int OutOfCoreRenderer::partCount() const { return int(impl_->parts.size()); }
int OutOfCoreRenderer::residentCount() const {
  return int(std::count_if(impl_->parts.begin(), impl_->parts.end(),
                           [](const Impl::Part& p) { return p.resident; }));
}
std::vector<int> OutOfCoreRenderer::residentParts() const {
  std::vector<int> out;
  for (size_t i = 0; i < impl_->parts.size(); ++i)
    if (impl_->parts[i].resident) out.push_back(int(i));
  return out;
}
std::vector<PartRange> OutOfCoreRenderer::ranges() const {
  std::vector<PartRange> out;
  for (const auto& p : impl_->parts) out.push_back(p.range);
  return out;
}
size_t OutOfCoreRenderer::budgetBytes() const { return impl_->partBudget; }
size_t OutOfCoreRenderer::partBytesLargest() const {
  size_t b = 0;
  for (const auto& p : impl_->parts) b = std::max(b, p.bytes);
  return b;
}
double OutOfCoreRenderer::openMs() const { return impl_->openMs; }

void OutOfCoreRenderer::render(const RenderParams& p, Image& out, OutOfCoreStats* stats) {
  OutOfCoreStats first;
  draw(p, out, &first, true);
  // Its parts widened the range its tables spanned: again, with the range every part agrees
  // on (all read now, unless the device held too few: then the frame says so anyway).
  if (impl_->applyLearned()) {
    draw(p, out, stats, true);
    if (stats) {
      stats->redrawnForRange = true;
      stats->uploads += first.uploads;
      stats->bytesUploaded += first.bytesUploaded;
      stats->readMs += first.readMs;
      stats->uploadMs += first.uploadMs;
      stats->totalMs += first.totalMs;
    }
  } else if (stats) {
    *stats = first;
  }
}

void OutOfCoreRenderer::preview(const RenderParams& p, Image& out, OutOfCoreStats* stats) {
  draw(p, out, stats, false);
}

void OutOfCoreRenderer::draw(const RenderParams& p, Image& out, OutOfCoreStats* stats,
                             bool converge) {
  const auto start = Clock::now();
  if (p.lighting != Lighting::Phong)
    throw inputError(std::string("an out-of-core frame is lit by phong only, not ") +
                     toString(p.lighting) + ": render it without --memory-budget");
  if (p.width <= 0 || p.height <= 0) throw inputError("the image size must be positive");
  Impl& m = *impl_;
  // The quick level gives way to the coarse level once that is made; a converged frame waits
  // for it (its range is the one the in-core frame has: no frame drawn twice for it).
  if (m.quick && (converge || m.src.coarseReady())) m.replaceQuick();
  if (m.cellsPending && (converge || m.residentBytes > 0)) m.makeConservativeCells();
  m.applyLearned();
  OutOfCoreStats s;
  s.parts = int(m.parts.size());
  RaycastParams k{};
  std::string options;
  m.full.updateSetup(p);
  // A sample a part takes may lie a step beyond its plane and its stencil 2 slices further:
  // beyond the apron it would read the clamped edge (as multi_device.h refuses).
  const double stepSlices = m.full.setup.stepMm / m.geom.spacingMm.z;
  if (stepSlices > double(m.o.apron - 2) + 1e-6) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  "the step (%.3g mm, %.3g slices) is longer than the %d slices an out-of-core "
                  "frame allows with its apron of %d",
                  m.full.setup.stepMm, stepSlices, m.o.apron - 2, m.o.apron);
    throw inputError(std::string(text) + ": render with a finer --step");
  }
  // The items: in a converged frame every part; in a preview the resident parts and the runs
  // of parts between them from the coarse level (one launch per run).
  std::vector<Impl::Item> items;
  for (size_t i = 0; i < m.parts.size(); ++i) {
    const PartRange& r = m.parts[i].range;
    if (converge || m.parts[i].resident) {
      items.push_back({r.first, r.end, int(i), 0.0});
    } else if (!items.empty() && items.back().part < 0) {
      items.back().end = r.end;
    } else {
      items.push_back({r.first, r.end, -1, 0.0});
    }
  }
  m.keys(items, p);
  // A preview with no part on the device draws none: the full volume's cells need no
  // classification (at first they are all conservative, 67 M of them for 8 GiB).
  const bool anyPart =
      std::any_of(items.begin(), items.end(), [](const Impl::Item& it) { return it.part >= 0; });
  m.setUp(m.full, m.fullSpace, p, k, options, anyPart);
  const size_t pixels = size_t(p.width) * size_t(p.height);
  clCall([&] {
    if (pixels > m.capacity) {
      m.colour = cl::Buffer(m.cl.context, CL_MEM_WRITE_ONLY, pixels * sizeof(cl_float4));
      m.order = cl::Buffer(m.cl.context, CL_MEM_WRITE_ONLY, pixels * sizeof(cl_float));
      m.accBuffer = cl::Buffer(m.cl.context, CL_MEM_READ_WRITE, pixels * sizeof(cl_float4));
      m.capacity = pixels;
    }
    m.cl.queue.enqueueFillBuffer(m.accBuffer, cl_float4{{0.0f, 0.0f, 0.0f, 0.0f}}, 0,
                                 pixels * sizeof(cl_float4));
    return 0;
  });
  bool coarseReady = false;
  auto drawCoarse = [&](const Impl::Item& it) {
    if (!coarseReady) {
      RaycastParams ck{};
      std::string co;
      m.coarseFrame->updateSetup(p);
      m.setUp(*m.coarseFrame, m.coarseSpace, p, ck, co);
      coarseReady = true;
    }
    Impl::Item c = it;
    c.part = -1;
    m.launch(c, p);
    s.fullResolution = false;
    s.partsCoarse += int(std::count_if(m.parts.begin(), m.parts.end(), [&](const Impl::Part& q) {
      return q.range.first >= it.first && q.range.end <= it.end;
    }));
  };
  m.kernelEvents.clear();
  m.copyEvents.clear();
  m.kernelMs = m.copyMs = 0.0;
  const auto partsStart = Clock::now();
  // Each part's position in this frame's order: what Belady's rule evicts by.
  std::vector<int> position(m.parts.size(), 0);
  for (size_t j = 0; j < items.size(); ++j)
    if (items[j].part >= 0) position[size_t(items[j].part)] = int(j);
  for (size_t j = 0; j < items.size(); ++j) {
    const Impl::Item& it = items[j];
    if (it.part < 0) {
      drawCoarse(it);
      continue;
    }
    Impl::Part& part = m.parts[size_t(it.part)];
    if (!part.resident) {
      bool fits = !s.deviceOutOfMemory && part.bytes <= m.partBudget;
      while (fits && m.residentBytes + part.bytes > m.partBudget) {
        // Evict the part needed again latest: one still to come in this frame by its
        // position, one already drawn in the next frame's (the same order).
        int victim = -1, latest = -1;
        for (size_t q = 0; q < m.parts.size(); ++q) {
          if (!m.parts[q].resident || int(q) == it.part) continue;
          const int next = position[q] > int(j) ? position[q] : int(items.size()) + position[q];
          if (next > latest) latest = next, victim = int(q);
        }
        if (victim < 0) break;
        m.evict(m.parts[size_t(victim)]);
      }
      if (fits) {
        try {
          m.upload(part, s);
        } catch (const Error& e) {
          if (e.kind() != Error::Kind::Device) throw;
          // The device is fuller than the budget said: hold what it holds now, and draw the
          // parts it cannot take from the coarse level.
          s.deviceOutOfMemory = true;
          m.partBudget = m.residentBytes;
          s.message = "the device could not take part " + std::to_string(it.part + 1) + " of " +
                      std::to_string(m.parts.size()) + " (" + mibText(part.bytes) +
                      ") beside the " + mibText(m.residentBytes) + " it holds (" + e.what() +
                      "); the parts it cannot hold are drawn from the coarse level: lower "
                      "--memory-budget, or free the device";
        }
      }
      if (!part.resident) {
        if (s.message.empty())
          s.message = "the device holds " + mibText(m.partBudget) +
                      " of parts since an allocation "
                      "failed, less than part " +
                      std::to_string(it.part + 1) + " (" + mibText(part.bytes) +
                      "): it is drawn from the coarse level; free the device "
                      "and open the volume again for full resolution";
        drawCoarse(it);
        continue;
      }
    }
    m.launch(it, p);
    ++s.partsFull;
  }
  m.acc.resize(pixels * 4);
  clCall([&] { return m.cl.queue.finish(); });
  m.spares.clear();  // an upload that failed left them: their launches are done
  s.partsMs = msSince(partsStart);
  clCall([&] {  // every event is done: the rest counted
    m.harvest();
    return 0;
  });
  s.kernelMs = m.kernelMs;
  if (s.pinned) s.uploadMs = m.copyMs;
  m.kernelEvents.clear();
  m.copyEvents.clear();
  s.overlapMs = std::max(0.0, s.readMs + s.uploadMs + s.kernelMs - s.partsMs);
  clCall([&] {
    m.cl.queue.enqueueReadBuffer(m.accBuffer, CL_TRUE, 0, pixels * sizeof(cl_float4), m.acc.data());
    return 0;
  });
  // The composite into bytes, the background behind.
  out.width = p.width;
  out.height = p.height;
  out.rgba.resize(pixels * 4);
  const glm::vec3 bg(p.background);
  parallelFor(size_t((p.height + 31) / 32), [&](size_t band) {
    const size_t y0 = band * 32, y1 = std::min(size_t(p.height), y0 + 32);
    for (size_t px = y0 * size_t(p.width); px < y1 * size_t(p.width); ++px) {
      const float* a = &m.acc[px * 4];
      glm::vec3 rgb = bg;
      if (p.mode == Mode::Dvr)
        rgb = glm::vec3(a[0], a[1], a[2]) + (1.0f - a[3]) * bg;
      else if (p.mode == Mode::Iso) {
        if (a[3] > 0.0f) rgb = glm::vec3(a[0], a[1], a[2]);
      } else if (a[3] > 0.0f && a[0] >= 0.0f) {
        rgb = glm::vec3(a[0]);
      }
      uint8_t* o = &out.rgba[px * 4];
      o[0] = toRgba8Byte(rgb.x);
      o[1] = toRgba8Byte(rgb.y);
      o[2] = toRgba8Byte(rgb.z);
      o[3] = 255;
    }
  });
  s.partsResident = residentCount();
  s.cellsKnown = m.rowKnown.empty() ? 1.0 : double(m.rowsKnown) / double(m.rowKnown.size());
  s.missingChunks = m.src.missingChunks();
  s.note = m.note;
  if (s.missingChunks) {
    const std::string missing = std::to_string(s.missingChunks) +
                                " chunks of the volume were missing where it was read: drawn "
                                "empty (their fill value); the store is incomplete, copy it again";
    s.note = s.note.empty() ? missing : s.note + "; " + missing;
  }
  s.shown = s.fullResolution ? "full" : m.quick ? "preview" : "coarse";
  // The coarse level's pass starts once the first image is out, not before: it would take
  // the CPU that image waits for.
  if (m.quick) m.src.startCoarse();
  s.totalMs = msSince(start);
  if (stats) *stats = s;
}

}  // namespace voxray
