#include "voxray/engine/path_tracer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "device_frame.h"
#include "path_majorants.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

cl_float4 row(const glm::dmat3& m, int r) {  // glm is column-major
  return {{float(m[0][r]), float(m[1][r]), float(m[2][r]), 0.0f}};
}

}  // namespace

RenderParams cinematicFrame(const RenderParams& p) {
  RenderParams q = p;
  q.mode = Mode::Dvr;
  q.shading = false;  // the raycaster's switches the kernel does not read: one program
  q.jitter = false;
  return q;
}

double pathMajorant(const Lut& lut, double referenceStepMm, double opacityCap) {
  double a = 0.0;
  for (const glm::vec4& e : lut.rgba) a = std::max(a, double(e.a));
  a = std::clamp(a, 0.0, opacityCap);
  return -std::log1p(-a) / referenceStepMm;
}

struct PathTracer::Impl {
  std::shared_ptr<DeviceFrame> frame;  // the raycaster's
  PathTracerOptions opts;
  std::string frameKey;  // toText of the frame being accumulated; empty: restart
  PathProgress progress;
  cl::Buffer accum, out;
  size_t pixels = 0;
  int width = 0, height = 0;
  PathMajorants majorants;
  bool volumeScanned = false;
  Lut majorantLut;  // the table (and step, cap) the grid on the device was made for
  double majorantStep = 0.0, majorantCap = 0.0;
  cl::Buffer majorantBuffer;

  // The majorant grid for this frame's table, rebuilt and uploaded when it changed.
  void updateMajorants(const DeviceFrame& f);
  // Sets the frame up for P (cinematicFrame) and uploads its parameters and table; returns
  // the one-ray-per-work-item switches they were built with.
  KernelSwitches prepare(const RenderParams& p);

  explicit Impl(std::shared_ptr<DeviceFrame> f) : frame(std::move(f)) {}
};

KernelSwitches PathTracer::Impl::prepare(const RenderParams& p) {
  DeviceFrame& f = *frame;
  f.updateSetup(p);
  KernelSwitches sw = kernelSwitches(p);  // one ray per work-item: no packets, no leaps
  // The paths ignore the gradient opacity (README): one program with or without it.
  sw.GRADIENT_OPACITY = 0;
  sw.TF2D = 0;  // likewise the 2D transfer function: the paths read its largest over gradient
  sw.STORAGE_IMAGE = f.storage == VolumeStorage::Image3d;
  sw.SLABS = f.device.plan().count();
  RaycastParams k = f.frameParams(p, sw);
  clCall([&] {
    f.uploadFrame(k);
    return 0;
  });
  return sw;
}

void PathTracer::Impl::updateMajorants(const DeviceFrame& f) {
  const Lut& lut = f.setup.lut;
  if (!volumeScanned) {
    majorants.setVolume(f.volume);
    volumeScanned = true;
  } else if (lut.rgba == majorantLut.rgba && lut.storedMin == majorantLut.storedMin &&
             lut.scale == majorantLut.scale && f.setup.referenceStepMm == majorantStep &&
             opts.opacityCap == majorantCap) {
    return;
  }
  const std::vector<float>& sigma = majorants.update(lut, f.setup.referenceStepMm, opts.opacityCap);
  clCall([&] {
    majorantBuffer = cl::Buffer(f.cl.context, CL_MEM_READ_ONLY, sigma.size() * sizeof(float));
    f.cl.queue.enqueueWriteBuffer(majorantBuffer, CL_TRUE, 0, sigma.size() * sizeof(float),
                                  sigma.data());
    return 0;
  });
  majorantLut = lut;
  majorantStep = f.setup.referenceStepMm;
  majorantCap = opts.opacityCap;
}

PathTracer::PathTracer(Raycaster& raycaster)
    : impl_(std::make_unique<Impl>(raycaster.deviceFrame())) {}
PathTracer::~PathTracer() = default;

PathProgress PathTracer::progress() const { return impl_->progress; }

void PathTracer::restart() {
  impl_->frameKey.clear();
  impl_->progress = PathProgress{};
}

void PathTracer::setOptions(const PathTracerOptions& o) {
  if (o.maxBounces < 1 || o.maxBounces > 64)
    throw inputError("path tracer bounces must be 1 ... 64, not " + std::to_string(o.maxBounces));
  if (!(o.opacityCap > 0.0 && o.opacityCap < 1.0))
    throw inputError("path tracer opacity cap must lie strictly between 0 and 1");
  impl_->opts = o;
  restart();
}

const PathTracerOptions& PathTracer::options() const { return impl_->opts; }

PathProgress PathTracer::accumulate(const RenderParams& params, int samples, Image& image) {
  auto start = Clock::now();
  Impl& m = *impl_;
  if (samples < 1) throw inputError("path samples per call must be at least 1");
  if (params.width < 1 || params.height < 1) throw inputError("the image size must be positive");
  std::string key = toText(params);
  if (key != m.frameKey) {
    m.progress = PathProgress{};
    m.frameKey = key;
  }
  RenderParams q = cinematicFrame(params);
  const KernelSwitches sw = m.prepare(q);
  const DeviceFrame& f = *m.frame;
  const FrameSetup& s = f.setup;
  const glm::dmat3& w2v = s.view.worldToVoxel;
  double majorant = pathMajorant(s.lut, s.referenceStepMm, m.opts.opacityCap);
  m.updateMajorants(f);
  glm::ivec3 cells = m.majorants.dims();
  cl_float4 lights = {{float(params.light.diffuse), float(params.light.ambient), float(majorant),
                       float(m.opts.opacityCap)}};
  cl_uint4 counters = {{cl_uint(m.opts.seed), cl_uint(m.progress.samples), cl_uint(samples),
                        cl_uint(m.opts.maxBounces)}};
  size_t pixels = size_t(params.width) * size_t(params.height);
  std::string opts = switchOptions(sw, false);  // no fast maths: logs of tiny numbers
  cl::Kernel kernel = f.cl.kernel("lighting/path_trace.cl", "path_trace", opts);
  image.width = params.width;
  image.height = params.height;
  image.rgba.resize(pixels * 4);
  clCall([&] {
    if (pixels > m.pixels) {
      m.accum = cl::Buffer(f.cl.context, CL_MEM_READ_WRITE, pixels * sizeof(cl_float4));
      m.out = cl::Buffer(f.cl.context, CL_MEM_WRITE_ONLY, pixels * 4);
      m.pixels = pixels;
    }
    cl_uint arg = f.device.setArgs(kernel, 0);
    kernel.setArg(arg++, f.paramsBuffer);
    kernel.setArg(arg++, f.lutBuffer);
    kernel.setArg(arg++, m.accum);
    kernel.setArg(arg++, m.out);
    kernel.setArg(arg++, m.majorantBuffer);
    kernel.setArg(arg++, cl_int4{{cells.x, cells.y, cells.z, 0}});
    kernel.setArg(arg++, row(w2v, 0));
    kernel.setArg(arg++, row(w2v, 1));
    kernel.setArg(arg++, row(w2v, 2));
    kernel.setArg(arg++, lights);
    kernel.setArg(arg++, counters);
    cl::NDRange local = f.cl.info.isGpu ? cl::NDRange(16, 8) : cl::NullRange;
    size_t gx = size_t(params.width), gy = size_t(params.height);
    if (f.cl.info.isGpu) {
      gx = (gx + 15) / 16 * 16;
      gy = (gy + 7) / 8 * 8;
    }
    f.cl.queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(gx, gy), local);
    f.cl.queue.enqueueReadBuffer(m.out, CL_TRUE, 0, pixels * 4, image.rgba.data());
    return 0;
  });
  m.width = params.width;
  m.height = params.height;
  m.progress.samples += samples;
  m.progress.seconds += secondsSince(start);
  return m.progress;
}

PathProgress PathTracer::run(const RenderParams& p, int samples, double seconds, Image& out,
                             double maxPassSeconds) {
  if (samples < 0 || seconds < 0.0 || (samples == 0 && seconds <= 0.0))
    throw inputError("give a sample count (--spp) or a time (--seconds) to path-trace for");
  restart();
  auto start = Clock::now();
  int batch = 1;
  for (;;) {
    int done = impl_->progress.samples;
    if (samples > 0) batch = std::min(batch, samples - done);
    auto t = Clock::now();
    accumulate(p, batch, out);
    double took = std::max(secondsSince(t), 1e-6), elapsed = secondsSince(start);
    if ((samples > 0 && impl_->progress.samples >= samples) ||
        (seconds > 0.0 && elapsed >= seconds))
      break;
    // The next launch: about maxPassSeconds, and no further than the time left.
    double budget = maxPassSeconds;
    if (seconds > 0.0) budget = std::min(budget, seconds - elapsed);
    batch = int(std::clamp(std::floor(budget / (took / batch)), 1.0, 65536.0));
  }
  return impl_->progress;
}

FloatImage PathTracer::radiance() const {
  const Impl& m = *impl_;
  FloatImage f;
  if (m.progress.samples == 0) return f;
  f.width = m.width;
  f.height = m.height;
  size_t pixels = size_t(m.width) * size_t(m.height);
  std::vector<cl_float4> sum(pixels);
  clCall([&] {
    m.frame->cl.queue.enqueueReadBuffer(m.accum, CL_TRUE, 0, pixels * sizeof(cl_float4),
                                        sum.data());
    return 0;
  });
  f.rgb.resize(pixels * 3);
  float n = float(m.progress.samples);
  for (size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c) f.rgb[i * 3 + c] = sum[i].s[c] / n;
  return f;
}

namespace {

// A frame's stats from the path tracer's progress after it (TOTALMS: the frame's wall time).
void setPathStats(FrameStats* stats, const PathProgress& g, double totalMs) {
  if (!stats) return;
  *stats = FrameStats{};
  stats->totalMs = totalMs;
  stats->pathSamples = g.samples;
  stats->pathSeconds = g.seconds;
  stats->variant = "path_trace";
}

}  // namespace

void PathTracer::render(const RenderParams& p, Image& out, FrameStats* stats) {
  auto start = Clock::now();
  PathProgress g = accumulate(p, 1, out);
  setPathStats(stats, g, secondsSince(start) * 1e3);
}

void PathTracer::renderRows(const RenderParams& p, Image& out, int, int, FrameStats* stats) {
  render(p, out, stats);
}

void PathTracer::renderStill(const RenderParams& p, const StillBudget& budget, Image& out,
                             FrameStats* stats) {
  PathProgress g = run(p, budget.samples, budget.seconds, out);
  setPathStats(stats, g, g.seconds * 1e3);
  if (stats) stats->kernelMs = g.seconds * 1e3;  // launches and read-back alike
}

}  // namespace voxray
