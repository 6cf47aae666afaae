#include "voxray/engine/raycaster.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "adaptive_image.h"
#include "device_frame.h"
#include "empty_space.h"
#include "label_cells.h"
#include "label_table.h"
#include "light_volume.h"
#include "overlay_cells.h"
#include "segment_table.h"  // kernels/: the table's size
#include "segment_tf.h"
#include "surface_field.h"
#include "surface_layer.h"  // kernels/: the pass's layout
#include "voxray/engine/overlay.h"
#include "voxray/engine/path_tracer.h"
#include "voxray/io/segmentation.h"
#include "voxray/io/volume.h"

namespace voxray {

struct Raycaster::Impl {
  std::shared_ptr<DeviceFrame> frame;  // shared with the path tracers made from this
  ContextImpl& cl;
  const Volume& volume;
  VolumeStorage& storage;
  DeviceVolume& device;
  cl::Buffer outBuffer;
  size_t outCapacity = 0;
  EmptySpace space;
  double emptySpaceMs = 0.0;  // the last space.upload (uploadTimes)
  LightVolume light;          // shadows, ao (issue 15): the light grid behind the table
  bool holdLight = false;     // holdLightGrid: keep the grid while only the light moves
  // The camera-relative light (followCamera) the grid was last built for: a drag holds the
  // grid only while the light keeps that place (a camera drag), not while the light itself
  // is dragged (its shadows are what that drag is for).
  std::optional<glm::dvec3> lightBuiltFor;
  // The frame's table buffer (DeviceFrame::lutAllocations) the current grid was copied
  // into, -1: none; and where in it (behind the tables, whose bytes change with the gradient
  // opacity).
  int lightCopiedInto = -1;
  size_t lightCopiedAt = 0;
  cl::Buffer countBuffer;                     // 64 sample counters (COUNT_SAMPLES)
  std::vector<glm::vec4>* hitsOut = nullptr;  // set by renderWithHits (HIT_OUTPUT)
  glm::ivec2 rows{0, 0};                      // set by renderRows: rows [x, y) only
  cl::Buffer hitBuffer;
  size_t hitCapacity = 0;
  RaycasterOptions opts;
  // Label-aware dvr (setSegmentation): the label map on the device, the segments, the
  // labels' macro-cell occupancy and the segment table last uploaded.
  bool labels = false;
  cl::Buffer labelBuffer, segmentBuffer;
  std::vector<Segment> segments;
  LabelCells labelCells;
  std::vector<glm::vec4> segmentsUploaded;
  // Per-segment transfer functions (segment_tf.h): their tables on the device as last
  // uploaded, and the macro cells they may show in, for that upload and segment table
  // (cleared when the label map changes).
  cl::Buffer segTfBuffer;
  size_t segTfCapacity = 0;
  std::vector<glm::vec4> segTfUploaded, segTfCellsTable, segTfCellsTfs;
  std::vector<uint8_t> segTfCells;
  // Fused dvr (setOverlay): the overlay's voxels, table and geometry (overlay.cl's ovol,
  // olut, ogeo) and the base cells where it may show.
  bool overlay = false;
  cl::Buffer overlayVolume, overlayLut, overlayCellBuffer, overlayGeometry;
  std::vector<uint8_t> overlayCellsShown;
  // Segments shown as surfaces (surfaceHits, surface_layer.cl): the fields by label (kept
  // while a segment is shown otherwise, dropped where an edit touches them), the labels whose
  // fields the device holds, in their order, and the pass's layer.
  std::map<uint8_t, SurfaceField> surfaceFields;
  float surfaceSigma = kSurfaceSigmaVoxels;
  int surfaceBuilds = 0;  // whole builds (an edit inside a field's box filters it again)
  std::vector<uint8_t> surfacesOnDevice;
  bool surfaceFieldsChanged = true;
  cl::Buffer surfaceFieldBuffer, surfaceGeoBuffer, surfaceColourBuffer, surfaceLayer, surfaceProbe;
  size_t surfaceLayerCapacity = 0, surfaceProbeCapacity = 0;
  std::vector<Raycaster::SurfaceHit>* probeOut = nullptr;  // set by surfaceHits
  AdaptiveImage adaptiveImage;                             // RenderParams::adaptiveImage's passes

  Impl(ClContext& ctx, const Volume& v, VolumeStorage s)
      : frame(std::make_shared<DeviceFrame>(ctx.impl(), v, s)),
        cl(frame->cl),
        volume(v),
        storage(frame->storage),
        device(frame->device),
        light(v) {}

  void upload();
  KernelSwitches switches(const RenderParams& p) const;
  std::string options(const KernelSwitches& s) const;
  bool packets() const;
  int lanes(const RenderParams& p) const;
  cl::NDRange local() const;
  std::unique_ptr<PathTracer> pathTracer;  // lighting cinematic, made on first use
  PathTracer& tracer(Raycaster& r);
  // Surfaces
  std::vector<uint8_t> shownSurfaces() const;
  void buildSurfaceFields(const Segmentation& seg);
  void uploadSurfaces(const std::vector<uint8_t>& shown);
  void surfacePass(const RenderParams& p, const KernelSwitches& sw, size_t y0, size_t y1,
                   bool probe);
};

// The labels of the segments a dvr frame draws as surfaces, in the list's order.
std::vector<uint8_t> Raycaster::Impl::shownSurfaces() const {
  std::vector<uint8_t> out;
  for (const Segment& s : segments) {
    if (!s.visible || s.display3d != Segment::Display3d::Surface) continue;
    auto it = surfaceFields.find(s.label);
    if (it == surfaceFields.end() || it->second.empty()) continue;
    if (out.size() < SURFACE_MAX) out.push_back(s.label);
  }
  return out;
}

// Fields for the surface segments that have none (a new surface, or one an edit touched).
void Raycaster::Impl::buildSurfaceFields(const Segmentation& seg) {
  for (const Segment& s : seg.segments) {
    if (!s.visible || s.display3d != Segment::Display3d::Surface) continue;
    if (surfaceFields.count(s.label)) continue;
    surfaceFields[s.label] = buildSurfaceField(seg, s.label, surfaceSigma);
    ++surfaceBuilds;
    surfaceFieldsChanged = true;
  }
  // Fields of segments no longer in the list go.
  for (auto it = surfaceFields.begin(); it != surfaceFields.end();) {
    if (!seg.find(it->first))
      it = surfaceFields.erase(it), surfaceFieldsChanged = true;
    else
      ++it;
  }
}

// The fields of SHOWN into one device buffer (fields, then block flags) and their geometry.
void Raycaster::Impl::uploadSurfaces(const std::vector<uint8_t>& shown) {
  if (!surfaceFieldsChanged && shown == surfacesOnDevice) return;
  std::vector<cl_int4> geo;
  size_t bytes = 0;
  for (uint8_t l : shown) {
    const SurfaceField& f = surfaceFields.at(l);
    bytes += f.values.size() + f.blocks.size();
  }
  if (bytes >= (size_t(1) << 31) || bytes > cl.info.maxAllocBytes)
    throw deviceError("the surfaces' fields need " + std::to_string(bytes) +
                      " bytes in one allocation: show fewer segments as surfaces");
  std::vector<uint8_t> all;
  all.reserve(bytes);
  for (uint8_t l : shown) {
    const SurfaceField& f = surfaceFields.at(l);
    const int at = int(all.size());
    all.insert(all.end(), f.values.begin(), f.values.end());
    const int blocksAt = int(all.size());
    all.insert(all.end(), f.blocks.begin(), f.blocks.end());
    geo.push_back({{f.lo.x, f.lo.y, f.lo.z, at}});
    geo.push_back({{f.dims.x, f.dims.y, f.dims.z, blocksAt}});
    geo.push_back({{f.blockDims.x, f.blockDims.y, f.blockDims.z, int(l)}});
  }
  clCall([&] {
    surfaceFieldBuffer = cl::Buffer(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                    std::max<size_t>(all.size(), 1), all.data());
    surfaceGeoBuffer = cl::Buffer(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                  std::max<size_t>(geo.size(), 1) * sizeof(cl_int4), geo.data());
    if (!surfaceColourBuffer())
      surfaceColourBuffer =
          cl::Buffer(cl.context, CL_MEM_READ_ONLY, SURFACE_MAX * sizeof(cl_float4));
    return 0;
  });
  surfacesOnDevice = shown;
  surfaceFieldsChanged = false;
}

// The surface pass over rows [Y0, Y1) into surfaceLayer (and the probe): enqueued before the
// frame's kernel on the same in-order queue, after its parameters are uploaded.
void Raycaster::Impl::surfacePass(const RenderParams& p, const KernelSwitches& sw, size_t y0,
                                  size_t y1, bool probe) {
  const std::vector<uint8_t> shown = shownSurfaces();
  uploadSurfaces(shown);
  std::vector<cl_float4> colours(SURFACE_MAX, cl_float4{{0.0f, 0.0f, 0.0f, 0.0f}});
  for (size_t i = 0; i < shown.size(); ++i) {
    const Segment& s = *std::find_if(segments.begin(), segments.end(),
                                     [&](const Segment& x) { return x.label == shown[i]; });
    const glm::vec3 c = glm::clamp(s.colour, 0.0f, 1.0f);
    colours[i] = {{c.r, c.g, c.b, std::clamp(s.opacity, 0.0f, 1.0f)}};
  }
  KernelSwitches only;  // the pass reads the frame's camera (ORTHO) alone
  only.ORTHO = sw.ORTHO;
  const std::string options = "-cl-fast-relaxed-math " + switchOptions(only, false) +
                              " -D SURFACE_PROBE=" + (probe ? "1" : "0");
  cl::Kernel kernel = cl.kernel("surface/surface_layer.cl", "surface_layer", options);
  const size_t pixels = size_t(p.width) * size_t(p.height);
  clCall([&] {
    if (2 * pixels * sizeof(cl_float4) > surfaceLayerCapacity) {
      surfaceLayer = cl::Buffer(cl.context, CL_MEM_READ_WRITE, 2 * pixels * sizeof(cl_float4));
      surfaceLayerCapacity = 2 * pixels * sizeof(cl_float4);
    }
    if (probe && 2 * pixels * sizeof(cl_float4) > surfaceProbeCapacity) {
      surfaceProbe = cl::Buffer(cl.context, CL_MEM_WRITE_ONLY, 2 * pixels * sizeof(cl_float4));
      surfaceProbeCapacity = 2 * pixels * sizeof(cl_float4);
    }
    cl.queue.enqueueWriteBuffer(surfaceColourBuffer, CL_FALSE, 0, SURFACE_MAX * sizeof(cl_float4),
                                colours.data());
    cl_uint arg = 0;
    kernel.setArg(arg++, frame->paramsBuffer);
    kernel.setArg(arg++, surfaceFieldBuffer);
    kernel.setArg(arg++, surfaceGeoBuffer);
    kernel.setArg(arg++, surfaceColourBuffer);
    kernel.setArg(arg++, cl_int(shown.size()));
    kernel.setArg(arg++, surfaceLayer);
    if (probe) kernel.setArg(arg++, surfaceProbe);
    if (y1 > y0)
      cl.queue.enqueueNDRangeKernel(kernel, cl::NDRange(0, y0),
                                    cl::NDRange(size_t(p.width), y1 - y0), cl::NullRange);
    // The colours' asynchronous write reads `colours`: wait before it goes out of scope.
    cl.queue.finish();
    return 0;
  });
}

void Raycaster::Impl::upload() {
  frame->upload(opts.maxSlabBytes);
  clCall([&] {
    countBuffer = cl::Buffer(cl.context, CL_MEM_READ_WRITE, 64 * sizeof(cl_uint));
    return 0;
  });
  const auto t0 = std::chrono::steady_clock::now();
  space.upload(cl, volume);
  // The first frame's value range from the cells: a pass over a 1 GiB volume saved (issue 38).
  frame->valueRange = ValueRange{int16_t(space.valueLo()), int16_t(space.valueHi())};
  emptySpaceMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

KernelSwitches Raycaster::Impl::switches(const RenderParams& p) const {
  KernelFacts f;
  f.emptySpaceSkipping = opts.emptySpaceSkipping;
  f.storageImage = storage == VolumeStorage::Image3d;
  f.slabs = device.plan().count();
  f.countSamples = opts.countSamples;
  f.hitOutput = hitsOut != nullptr;
  f.packetLanes = packets() ? lanes(p) : 0;
  f.labels = labels && p.mode == Mode::Dvr && !changesNothing(segmentTable(segments, p));
  f.segmentTf = f.labels && anySegmentTf(segmentTfSlots(segments, p));
  f.overlay = overlay;
  f.surfaces = labels && p.mode == Mode::Dvr && !shownSurfaces().empty();
  f.preintegrate = p.preintegrate;
  return kernelSwitches(p, f);
}

std::string Raycaster::Impl::options(const KernelSwitches& s) const {
  return "-cl-fast-relaxed-math " + switchOptions(s, opts.kernel == RaycasterOptions::Kernel::Uber);
}

bool Raycaster::Impl::packets() const {
  // march_lanes.cl reads one volume argument and indexes voxels with int.
  return opts.packets && opts.kernel == RaycasterOptions::Kernel::Specialised &&
         storage == VolumeStorage::Buffer && !cl.info.isGpu && device.plan().count() == 1 &&
         volume.voxelCount() < (size_t(1) << 31);
}

int Raycaster::Impl::lanes(const RenderParams&) const {
  if (opts.packetLanes != 0) return opts.packetLanes;
  // AVX-512, VTK's orbit: CThead dvr 16 lanes 1.22x faster than 8; mip (per-lane spans,
  // docs/bench/README.md session 7) faster at 16 on CThead and the 512x512x400 CT.
  return cl.info.nativeFloatWidth >= 16 ? 16 : 8;
}

cl::NDRange Raycaster::Impl::local() const {
  // The caller rounds the global size up to whole groups; the kernel drops extra items.
  if (opts.localX <= 0 || opts.localY <= 0) {
    // GPUs: 16x8 pixel tiles keep neighbouring rays' texture reads in cache; on an H200
    // 1920x1080 dvr ran 1.38x faster than with the driver's choice (docs/bench).
    if (cl.info.isGpu) return cl::NDRange(16, 8);
    // Packets: PoCL chose a few large groups (128x24 packets at 512x384), and the cores
    // idled 15-20 % of a CThead dvr frame waiting for the last, slowest one. Groups of 4x4
    // packets keep them both busy (idle 2-3 %, vmstat).
    if (packets()) return cl::NDRange(4, 4);
    return cl::NullRange;
  }
  return cl::NDRange(size_t(opts.localX), size_t(opts.localY));
}

Raycaster::Raycaster(ClContext& ctx, const Volume& volume, VolumeStorage storage)
    : impl_(std::make_unique<Impl>(ctx, volume, storage)) {
  impl_->upload();
}

Raycaster::~Raycaster() = default;

VolumeStorage Raycaster::storage() const { return impl_->storage; }

std::string Raycaster::variantOptions(const RenderParams& p) const {
  return impl_->options(impl_->switches(p));
}

Raycaster::UploadTimes Raycaster::uploadTimes() const {
  return {impl_->device.uploadMs(), impl_->emptySpaceMs};
}

int Raycaster::slabCount() const { return impl_->device.plan().count(); }

void Raycaster::setOptions(const RaycasterOptions& options) {
  Impl& m = *impl_;
  if (options.packetLanes != 0 && options.packetLanes != 8 && options.packetLanes != 16)
    throw inputError("packet lanes must be 8, 16 or 0 (automatic), not " +
                     std::to_string(options.packetLanes));
  bool reslab = options.maxSlabBytes != m.opts.maxSlabBytes;
  if (reslab) m.device.upload(m.cl, m.volume, m.storage, options.maxSlabBytes);
  m.opts = options;
}

const RaycasterOptions& Raycaster::options() const { return impl_->opts; }

int Raycaster::classifications() const { return impl_->space.classifications(); }
int Raycaster::isoBlockScans() const { return impl_->space.isoBlockScans(); }

int Raycaster::lightingBuilds() const { return impl_->light.builds(); }

int Raycaster::lightingSigmaBuilds() const { return impl_->light.sigmaBuilds(); }

void Raycaster::holdLightGrid(bool hold) { impl_->holdLight = hold; }

bool Raycaster::lightGridHeld() const { return impl_->holdLight; }

int Raycaster::lightingHeldFrames() const { return impl_->light.heldFrames(); }

std::shared_ptr<DeviceFrame> Raycaster::deviceFrame() const { return impl_->frame; }

void Raycaster::setSegmentation(const Segmentation& seg) {
  Impl& m = *impl_;
  if (!sameGrid(seg.grid, gridOf(m.volume)) || seg.labels.size() != m.volume.voxelCount())
    throw inputError(
        "the segmentation's label map does not lie on the volume's voxels (dims, spacing, "
        "origin or direction differ): make it on this volume or resample it to it");
  if (seg.labels.size() > m.cl.info.maxAllocBytes)
    throw deviceError("the label map needs " + std::to_string(seg.labels.size()) +
                      " bytes in one allocation; the device allows " +
                      std::to_string(m.cl.info.maxAllocBytes) +
                      ": render this volume without labels or on a device with more memory");
  clCall([&] {
    m.labelBuffer = cl::Buffer(m.cl.context, CL_MEM_READ_ONLY, seg.labels.size());
    m.cl.queue.enqueueWriteBuffer(m.labelBuffer, CL_TRUE, 0, seg.labels.size(), seg.labels.data());
    if (!m.segmentBuffer())
      m.segmentBuffer = cl::Buffer(m.cl.context, CL_MEM_READ_ONLY,
                                   VOXRAY_SEGMENT_TABLE_FLOAT4S * sizeof(cl_float4));
    return 0;
  });
  m.labelCells = computeLabelCells(seg);
  m.segments = seg.segments;
  m.segmentsUploaded.clear();
  m.segTfCellsTable.clear();
  m.labels = true;
  m.surfaceFields.clear();  // a new label map
  m.surfaceFieldsChanged = true;
  m.buildSurfaceFields(seg);
}

void Raycaster::updateSegmentation(const Segmentation& seg, glm::ivec3 lo, glm::ivec3 hi) {
  Impl& m = *impl_;
  if (!m.labels || seg.labels.size() != m.volume.voxelCount() || seg.grid.dims != m.volume.dims)
    return setSegmentation(seg);
  m.segments = seg.segments;
  lo = glm::clamp(lo, glm::ivec3(0), m.volume.dims - 1);
  hi = glm::clamp(hi, glm::ivec3(0), m.volume.dims - 1);
  if (glm::any(glm::greaterThan(lo, hi))) return m.buildSurfaceFields(seg);
  // Fields the edit may have changed: filtered again around the box, or, where the segment grew
  // out of the box a field was built over, dropped and built again (a surface segment's) below.
  for (auto it = m.surfaceFields.begin(); it != m.surfaceFields.end();) {
    if (!surfaceFieldTouched(it->second, seg, lo, hi)) {
      ++it;
      continue;
    }
    m.surfaceFieldsChanged = true;
    if (updateSurfaceField(it->second, seg, lo, hi)) {
      ++it;
    } else {
      it = m.surfaceFields.erase(it);
    }
  }
  m.buildSurfaceFields(seg);
  // Whole planes lo.z ... hi.z: one contiguous write (a box's rows would be many small ones).
  const size_t plane = size_t(m.volume.dims.x) * size_t(m.volume.dims.y);
  clCall([&] {
    m.cl.queue.enqueueWriteBuffer(m.labelBuffer, CL_TRUE, size_t(lo.z) * plane,
                                  size_t(hi.z - lo.z + 1) * plane,
                                  seg.labels.data() + size_t(lo.z) * plane);
    return 0;
  });
  updateLabelCells(m.labelCells, seg, lo, hi);
  m.segTfCellsTable.clear();
  m.space.setShownCells(m.cl, {});  // recomputed for the next labelled frame
}

void Raycaster::clearSegmentation() {
  Impl& m = *impl_;
  m.labels = false;
  m.labelBuffer = cl::Buffer();
  m.segments.clear();
  m.labelCells = LabelCells{};
  m.segmentsUploaded.clear();
  m.segTfCellsTable.clear();
  m.space.setShownCells(m.cl, {});
  m.surfaceFields.clear();
  m.surfacesOnDevice.clear();
  m.surfaceFieldBuffer = cl::Buffer();
  m.surfaceFieldsChanged = true;
}

bool Raycaster::hasSegmentation() const { return impl_->labels; }

void Raycaster::setSurfaceSigma(float sigmaVoxels) {
  Impl& m = *impl_;
  if (!(sigmaVoxels >= 0.0f) || sigmaVoxels > 8.0f)
    throw inputError("the surfaces' smoothing sigma must be 0 ... 8 voxels, not " +
                     std::to_string(sigmaVoxels));
  m.surfaceSigma = sigmaVoxels;
  m.surfaceFields.clear();  // built again at the next setSegmentation
  m.surfaceFieldsChanged = true;
}

int Raycaster::surfaceFieldBuilds() const { return impl_->surfaceBuilds; }

std::vector<Raycaster::SurfaceHit> Raycaster::surfaceHits(const RenderParams& params) {
  std::vector<SurfaceHit> hits;
  struct Reset {
    Impl& m;
    ~Reset() { m.probeOut = nullptr; }
  } reset{*impl_};
  impl_->probeOut = &hits;
  Image scratch;
  render(params, scratch);
  return hits;
}

std::vector<std::string> Raycaster::setOverlay(const Volume& o, const TransferFunction& tf) {
  Impl& m = *impl_;
  if (o.voxelCount() == 0 || o.voxels.size() != o.voxelCount())
    throw inputError("the overlay has no voxels: load a volume to fuse");
  checkOverlayFits(o.byteSize(), m.cl.info.maxAllocBytes);
  const Lut lut = bakeLut(tf, o);
  const glm::dmat4 map = overlayVoxelMap(m.volume, o);
  // overlay.cl's ogeo: the map's rows, the dims and last entry, the table's placement.
  std::vector<cl_float4> geo(5);
  for (int r = 0; r < 3; ++r)
    geo[size_t(r)] = {{float(map[0][r]), float(map[1][r]), float(map[2][r]), float(map[3][r])}};
  geo[3] = {{float(o.dims.x), float(o.dims.y), float(o.dims.z), float(lut.rgba.size() - 1)}};
  // Whether the table is transparent only below its first visible entry: fused mip may then
  // leave out the macro cells where the overlay shows nothing (overlay.cl's overlay_mip).
  // Its largest opacity is what fused mip lays over the grey (overlayMipOpacity).
  bool seen = false, prefixOnly = true;
  for (const glm::vec4& e : lut.rgba) {
    seen = seen || e.a > 0.0f;
    prefixOnly = prefixOnly && !(seen && !(e.a > 0.0f));
  }
  geo[4] = {{float(lut.storedMin), float(lut.scale), prefixOnly ? 1.0f : 0.0f,
             float(overlayMipOpacity(lut))}};
  m.overlayCellsShown = overlayCells(m.volume, o, lut, map);
  clCall([&] {
    m.overlayCellBuffer = cl::Buffer(m.cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                     m.overlayCellsShown.size(), m.overlayCellsShown.data());
    m.overlayVolume = cl::Buffer(m.cl.context, CL_MEM_READ_ONLY, o.byteSize());
    m.cl.queue.enqueueWriteBuffer(m.overlayVolume, CL_TRUE, 0, o.byteSize(), o.voxels.data());
    m.overlayLut =
        cl::Buffer(m.cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                   lut.rgba.size() * sizeof(cl_float4), const_cast<glm::vec4*>(lut.rgba.data()));
    m.overlayGeometry = cl::Buffer(m.cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                   geo.size() * sizeof(cl_float4), geo.data());
    return 0;
  });
  m.overlay = true;
  return overlayWarnings(m.volume, o);
}

void Raycaster::clearOverlay() {
  Impl& m = *impl_;
  m.overlay = false;
  m.overlayVolume = m.overlayLut = m.overlayCellBuffer = m.overlayGeometry = cl::Buffer();
  m.overlayCellsShown.clear();
  m.space.setOverlayCells(m.cl, {});
}

bool Raycaster::hasOverlay() const { return impl_->overlay; }

PathTracer& Raycaster::Impl::tracer(Raycaster& r) {
  if (!pathTracer) pathTracer = std::make_unique<PathTracer>(r);
  return *pathTracer;
}

Renderer& Raycaster::rendererFor(const RenderParams& p) {
  if (p.lighting == Lighting::Cinematic) return impl_->tracer(*this);
  return *this;
}

void Raycaster::setPathTracerOptions(const PathTracerOptions& options) {
  impl_->tracer(*this).setOptions(options);
}

void Raycaster::render(const RenderParams& p, Image& out, FrameStats* stats) {
  auto start = std::chrono::steady_clock::now();
  if (p.lighting == Lighting::Cinematic) {
    if (!impl_->hitsOut)
      throw inputError(
          "the raycaster renders phong, shadows and ao; a cinematic frame is the "
          "path tracer's: render it through Raycaster::rendererFor");
    RenderParams phong = p;  // a pick's hits come from the phong frame: paths find no surface
    phong.lighting = Lighting::Phong;
    return render(phong, out, stats);
  }
  Impl& m = *impl_;
  DeviceFrame& f = *m.frame;
  KernelSwitches sw = m.switches(p);
  f.updateSetup(p, sw.PREINT != 0);
  const FrameSetup& s = f.setup;

  RaycastParams k = f.frameParams(p, sw);
  glm::ivec3 cells = m.space.dims();
  k.cells = {{cells.x, cells.y, cells.z, 0}};
  if (sw.LIGHTING) m.light.prepare(s, k);
  std::vector<glm::vec4> segmentTableNow;
  if (sw.LABELS) segmentTableNow = segmentTable(m.segments, p);
  std::vector<glm::vec4> segTfNow;  // SEGMENT_TF: the segments' own tables (segment_tf.h)
  if (sw.SEGMENT_TF) {
    const std::array<int, 256> slots = segmentTfSlots(m.segments, p);
    const std::vector<Lut> luts = bakeSegmentTfs(slots, p, m.volume, s.lut);
    segTfNow = packSegmentTfs(luts);
    // The cells they may show in: again only when the tables, factors or label map changed.
    if (m.opts.emptySpaceSkipping &&
        (segTfNow != m.segTfCellsTfs || segmentTableNow != m.segTfCellsTable)) {
      m.segTfCells =
          segmentTfCells(m.labelCells, m.space.cells().minMax, slots, luts, segmentTableNow);
      m.segTfCellsTable = segmentTableNow;
      m.segTfCellsTfs = segTfNow;
    }
  }

  size_t pixels = size_t(p.width) * size_t(p.height);
  out.width = p.width;
  out.height = p.height;
  out.rgba.resize(pixels * 4);  // the same size keeps the rows renderRows does not render
  const bool band = m.rows.y > m.rows.x && !m.hitsOut;
  const int y0 = band ? std::clamp(m.rows.x, 0, p.height) : 0;
  const int y1 = band ? std::clamp(m.rows.y, y0, p.height) : p.height;
  const size_t rowBytes = size_t(p.width) * 4;
  std::string opts = m.options(sw);
  cl::Kernel kernel = m.cl.kernel("raycast.cl", "raycast", opts);
  // Image-space adaptive sampling (adaptive_image.h): whole frames of pixels only; hits,
  // probes, surfaces and the overlay read or write per pixel what its passes do not lay out.
  const bool adaptive =
      wantsAdaptiveImage(p) && !band && !m.hitsOut && !m.probeOut && !sw.SURFACES && !sw.OVERLAY;
  cl::Kernel lattice, refine;
  if (adaptive) {
    KernelSwitches pass = sw;
    pass.IMAGE_PASS = 1;
    pass.HIT_OUTPUT = p.mode == Mode::Iso;  // the hits' depths for the flags (ImageDepth)
    lattice = m.cl.kernel("raycast.cl", "raycast", m.options(pass));
    pass.HIT_OUTPUT = 0;
    pass.IMAGE_PASS = 2;
    refine = m.cl.kernel("raycast.cl", "raycast", m.options(pass));
    const ImageLattice l = imageLattice(p.width, p.height, p.adaptiveImageSpacing);
    k.image_pass = {{l.k, l.cols, l.rows, 0}};
  }
  std::vector<cl::Event> passes;  // the adaptive frame's kernels
  cl::Event done;
  std::array<cl_uint, 64> counts{};
  double lightingMs = 0.0;
  clCall([&] {
    size_t tableBytes = f.tableBytes();  // the light grid goes behind
    if (pixels * 4 > m.outCapacity) {
      m.outBuffer = cl::Buffer(m.cl.context, CL_MEM_WRITE_ONLY, pixels * 4);
      m.outCapacity = pixels * 4;
    }
    cl::CommandQueue& q = m.cl.queue;
    f.uploadFrame(k, sw.LIGHTING ? m.light.bytes() : 0);
    // mip leaps by occupancy only in packets; one ray per work-item reads each cell's max.
    bool leaps = p.mode != Mode::Mip || m.packets();
    if (sw.LABELS && segmentTableNow != m.segmentsUploaded) {
      m.segmentsUploaded = segmentTableNow;  // the asynchronous write reads this copy
      q.enqueueWriteBuffer(m.segmentBuffer, CL_FALSE, 0,
                           m.segmentsUploaded.size() * sizeof(cl_float4),
                           m.segmentsUploaded.data());
    }
    // dvr leaps the cells where no label shows (LabelCells) as it leaps transparent ones.
    if (p.mode == Mode::Dvr && m.opts.emptySpaceSkipping)
      m.space.setShownCells(
          m.cl, sw.LABELS ? cellsShown(m.labelCells, segmentTableNow) : std::vector<uint8_t>{});
    // ... and leaps no cell where the overlay or a segment's own table may show.
    if (p.mode == Mode::Dvr && m.opts.emptySpaceSkipping) {
      std::vector<uint8_t> occupied = sw.OVERLAY ? m.overlayCellsShown : std::vector<uint8_t>{};
      if (sw.SEGMENT_TF && occupied.empty())
        occupied = m.segTfCells;
      else if (sw.SEGMENT_TF)
        for (size_t c = 0; c < occupied.size() && c < m.segTfCells.size(); ++c)
          occupied[c] |= m.segTfCells[c];
      m.space.setOverlayCells(m.cl, occupied);
    }
    if (sw.SEGMENT_TF && segTfNow != m.segTfUploaded) {
      const size_t bytes = segTfNow.size() * sizeof(cl_float4);
      if (bytes > m.segTfCapacity) {
        m.segTfBuffer = cl::Buffer(m.cl.context, CL_MEM_READ_ONLY, bytes);
        m.segTfCapacity = bytes;
      }
      m.segTfUploaded = segTfNow;  // the asynchronous write reads this copy
      q.enqueueWriteBuffer(m.segTfBuffer, CL_FALSE, 0, bytes, m.segTfUploaded.data());
    }
    if (m.opts.emptySpaceSkipping && leaps)
      // PREINT reads table entries a row's spacing around a value: skipping reads them too.
      m.space.classify(m.cl, f.paramsBuffer, f.lutBuffer, k, p.mode,
                       sw.PREINT ? s.preint.occupancy : s.lut, sw.ADAPTIVE != 0, sw.PACKET != 0,
                       sw.ISO_BLOCK_TRIES > 0);
    if (sw.LIGHTING) {
      KernelSwitches storage;  // light_volume.cl reads the volume only: one build per storage
      storage.STORAGE_IMAGE = sw.STORAGE_IMAGE;
      storage.SLABS = sw.SLABS;
      if (m.light.update(
              m.cl, m.device, "-cl-fast-relaxed-math " + switchOptions(storage, false), sw.LIGHTING,
              p.mode == Mode::Iso, f.paramsBuffer, f.lutBuffer,
              // the labels' leaps are not the light's (it ignores the labels)
              m.opts.emptySpaceSkipping && p.mode == Mode::Dvr && !sw.LABELS && !sw.OVERLAY
                  ? &m.space.leap()
                  : nullptr,
              k, s.lut.rgba,
              m.holdLight && p.light.followCamera && m.lightBuiltFor == p.light.position)) {
        lightingMs = m.light.lastMs();
        m.lightBuiltFor = p.light.followCamera ? std::optional(p.light.position) : std::nullopt;
        m.lightCopiedInto = -1;
      }
      if (m.lightCopiedInto != f.lutAllocations || m.lightCopiedAt != tableBytes)
        m.light.copyInto(m.cl, f.lutBuffer, tableBytes);
      m.lightCopiedInto = f.lutAllocations;
      m.lightCopiedAt = tableBytes;
    }
    if (m.opts.countSamples)
      q.enqueueWriteBuffer(m.countBuffer, CL_FALSE, 0, sizeof(counts), counts.data());
    // Segments shown as surfaces: their layer first (the same rows), which the march reads.
    if (sw.SURFACES) m.surfacePass(p, sw, size_t(y0), size_t(y1), m.probeOut != nullptr);
    if (m.hitsOut) {
      if (pixels * sizeof(cl_float4) > m.hitCapacity) {
        m.hitBuffer = cl::Buffer(m.cl.context, CL_MEM_WRITE_ONLY, pixels * sizeof(cl_float4));
        m.hitCapacity = pixels * sizeof(cl_float4);
      }
      m.hitsOut->resize(pixels);
    }
    // The arguments every pass of raycast.cl takes; returns the next argument's index.
    auto setArgs = [&](cl::Kernel& kn, const cl::Buffer* hits) {
      cl_uint arg = m.device.setArgs(kn, 0);  // vol, or vol0 .. per slab
      kn.setArg(arg++, f.paramsBuffer);
      kn.setArg(arg++, f.lutBuffer);
      kn.setArg(arg++, m.outBuffer);
      kn.setArg(arg++, m.space.leap());
      kn.setArg(arg++, m.space.range());
      kn.setArg(arg++, m.countBuffer);
      if (hits) kn.setArg(arg++, *hits);
      if (sw.LABELS) {  // LABEL_PARAMS (kernels/classification/labels.cl)
        kn.setArg(arg++, m.labelBuffer);
        kn.setArg(arg++, m.segmentBuffer);
        if (sw.SEGMENT_TF) kn.setArg(arg++, m.segTfBuffer);  // SEGTF_PARAMS (segment_tf.cl)
      }
      if (sw.OVERLAY) {  // OVERLAY_PARAMS (kernels/classification/overlay.cl)
        kn.setArg(arg++, m.overlayVolume);
        kn.setArg(arg++, m.overlayLut);
        kn.setArg(arg++, m.overlayCellBuffer);
        kn.setArg(arg++, m.overlayGeometry);
      }
      if (sw.SURFACES) kn.setArg(arg++, m.surfaceLayer);  // SURFACE_PARAMS (surfaces.cl)
      return arg;
    };
    cl::NDRange local = m.local();
    // A band starts at the work-item row holding Y0: the kernels take their pixel from
    // get_global_id, which counts the offset, and drop items past the image.
    size_t gx = size_t(p.width), gy = size_t(y1), oy = size_t(y0);
    if (m.packets()) {  // one work-item per 4 x (lanes / 4) pixels
      // MIP_HALVES packets of 4 x (lanes / 4) pixels, one below the other (mip_packet.cl).
      size_t rows = size_t(sw.LANES / 4) * size_t(sw.MIP_HALVES);
      gx = (gx + 3) / 4;
      gy = (gy + rows - 1) / rows;
      oy /= rows;
    }
    gy -= oy;
    if (local.dimensions() == 2) {
      gx = (gx + local[0] - 1) / local[0] * local[0];
      gy = (gy + local[1] - 1) / local[1] * local[1];
    }
    if (adaptive) {
      ImageDepth depth;
      depth.on = p.mode == Mode::Iso;
      depth.eye = k.eye_v;
      depth.forward = k.forward_v;
      depth.ortho = sw.ORTHO != 0;
      setArgs(lattice, depth.on ? &m.adaptiveImage.hits(m.cl, pixels) : nullptr);
      const cl_uint refineArg = setArgs(refine, nullptr);
      RaycastGrid grid{m.packets(), size_t(sw.LANES / 4) * size_t(sw.MIP_HALVES), local};
      m.adaptiveImage.enqueue(m.cl, p, lattice, refine, refineArg, m.outBuffer, grid, depth,
                              passes);
    } else {
      setArgs(kernel, m.hitsOut ? &m.hitBuffer : nullptr);
      q.enqueueNDRangeKernel(kernel, cl::NDRange(0, oy), cl::NDRange(gx, gy), local, nullptr,
                             &done);
    }
    if (m.opts.countSamples)
      q.enqueueReadBuffer(m.countBuffer, CL_FALSE, 0, sizeof(counts), counts.data());
    if (m.hitsOut)
      q.enqueueReadBuffer(m.hitBuffer, CL_FALSE, 0, pixels * sizeof(cl_float4), m.hitsOut->data());
    q.enqueueReadBuffer(m.outBuffer, CL_TRUE, size_t(y0) * rowBytes, size_t(y1 - y0) * rowBytes,
                        out.rgba.data() + size_t(y0) * rowBytes);
    if (m.probeOut) {
      std::vector<cl_float4> probe(2 * pixels, cl_float4{{0.0f, 0.0f, 0.0f, 0.0f}});
      if (sw.SURFACES)
        q.enqueueReadBuffer(m.surfaceProbe, CL_TRUE, 0, probe.size() * sizeof(cl_float4),
                            probe.data());
      m.probeOut->assign(pixels, SurfaceHit{});
      for (size_t i = 0; i < pixels; ++i) {
        const cl_float4& a = probe[2 * i];
        const cl_float4& n = probe[2 * i + 1];
        (*m.probeOut)[i] = {glm::vec3(a.s[0], a.s[1], a.s[2]), glm::vec3(n.s[0], n.s[1], n.s[2]),
                            int(std::lround(a.s[3]))};
      }
    }
    return 0;
  });
  if (stats) {
    stats->variant = opts;
    stats->lightingMs = lightingMs;
    stats->samples = 0.0;
    stats->adaptiveBlocks = adaptive ? m.adaptiveImage.blocks() : 0;
    stats->adaptiveRefined = adaptive ? m.adaptiveImage.refined() : 0;
    for (cl_uint c : counts) stats->samples += double(c);
    try {
      if (!adaptive) passes = {done};
      stats->kernelMs = 0.0;  // the adaptive frame's: its passes, flags and fill together
      for (const cl::Event& e : passes) {
        cl_ulong t0 = e.getProfilingInfo<CL_PROFILING_COMMAND_START>();
        cl_ulong t1 = e.getProfilingInfo<CL_PROFILING_COMMAND_END>();
        stats->kernelMs += double(t1 - t0) * 1e-6;
      }
    } catch (const cl::Error&) {
      stats->kernelMs = 0.0;  // some drivers do not profile; the wall time still stands
    }
    stats->totalMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
}

void Raycaster::renderRows(const RenderParams& params, Image& out, int y0, int y1,
                           FrameStats* stats) {
  struct Reset {
    Impl& m;
    ~Reset() { m.rows = {0, 0}; }
  } reset{*impl_};
  impl_->rows = {y0, y1};
  render(params, out, stats);
}

Image Raycaster::renderWithHits(const RenderParams& params, std::vector<glm::vec4>& hits,
                                FrameStats* stats) {
  struct Reset {  // the next plain render() must not write hits again
    Impl& m;
    ~Reset() { m.hitsOut = nullptr; }
  } reset{*impl_};
  impl_->hitsOut = &hits;
  Image out;
  render(params, out, stats);
  return out;
}

}  // namespace voxray
