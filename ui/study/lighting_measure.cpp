#include "lighting_measure.h"

#include <algorithm>
#include <cstdio>

#include "voxray/engine/cl_context.h"
#include "voxray/engine/monte_carlo_reference.h"
#include "voxray/engine/path_tracer.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/engine/step.h"
#include "voxray/io/error.h"
#include "voxray/io/statistics.h"
#include "voxray/lab/accuracy.h"
#include "voxray/lab/accuracy_sweep.h"

namespace voxray {

namespace {

void check(const std::atomic<bool>* cancel) {
  if (cancel && cancel->load()) throw cancelledError("lighting measurement cancelled");
}

std::string stepText(double voxels) {
  char b[64];
  if (voxels < 1.0)
    std::snprintf(b, sizeof b, "1/%g-voxel steps", 1.0 / voxels);
  else
    std::snprintf(b, sizeof b, "%g-voxel steps", voxels);
  return b;
}

FloatImage clamped(FloatImage f) {
  for (float& x : f.rgb) x = std::clamp(x, 0.0f, 1.0f);
  return f;
}

LightingMeasurement measureGridModel(Raycaster& rc, const Volume& v, const RenderParams& p,
                                     const LightingMeasureOptions& o,
                                     const std::atomic<bool>* cancel) {
  LightingMeasurement m;
  m.lighting = p.lighting;
  m.width = p.width;
  m.height = p.height;
  // A first frame with the clip box a hair smaller compiles the kernels (and the grid's);
  // the frame itself then rebuilds the grid warm, which is the precomputation's cost.
  RenderParams warm = p;
  warm.clip.hi.x = std::max(warm.clip.lo.x + 0.01, warm.clip.hi.x - 1e-3);
  rc.render(warm);
  check(cancel);
  Image img;
  std::vector<double> ms;
  for (int i = 0; i < std::max(1, o.frames); ++i) {
    FrameStats st;
    rc.render(p, img, &st);
    if (i == 0) m.precomputeMs = st.lightingMs;
    ms.push_back(st.totalMs - st.lightingMs);
  }
  m.msPerFrame = median(ms);
  check(cancel);
  const double h = v.minSpacingMm();
  // The sweep's fine reference (voxray-cli accuracy): trilinear, its bisections.
  RenderParams ref =
      fineParams(p, Interp::Linear, stepMmOf(o.referenceStepVoxels, h), SweepOptions{}.fineRefine);
  FloatImage truth;
  if (p.lighting == Lighting::Phong) {
    truth = renderReferenceFloat(v, ref);
    m.reference = "the reference renderer (exact), " + stepText(o.referenceStepVoxels);
  } else {
    MonteCarloOptions mc;
    mc.samples = o.referenceSamples;
    mc.stepMm = stepMmOf(o.rayStepVoxels, h);
    MonteCarloImage r = renderMonteCarlo(v, ref, mc);
    truth = std::move(r.mean);
    m.referenceSamples = r.samples;
    m.referenceStdError = r.meanStdError();
    char b[160];
    std::snprintf(b, sizeof b,
                  "the Monte Carlo reference, %d samples (mean standard error %.2g), %s", r.samples,
                  m.referenceStdError, stepText(o.referenceStepVoxels).c_str());
    m.reference = b;
  }
  ImageError e = compareImages(toFloatImage(img), truth);
  m.psnrDb = e.psnrDb;
  m.ssim = e.ssim;
  return m;
}

LightingMeasurement measureCinematic(Raycaster& rc, const RenderParams& p,
                                     const LightingMeasureOptions& o,
                                     const std::atomic<bool>* cancel) {
  LightingMeasurement m;
  m.lighting = Lighting::Cinematic;
  m.width = p.width;
  m.height = p.height;
  PathTracer pt(rc);
  PathTracerOptions opt;
  opt.seed = 2;  // the reference's paths are independent of the measured image's
  pt.setOptions(opt);
  Image img;
  // In passes, so that a cancel is seen within a pass or so.
  while (pt.progress().samples < o.cinematicReferenceSpp) {
    pt.accumulate(p, std::min(8, o.cinematicReferenceSpp - pt.progress().samples), img);
    check(cancel);
  }
  FloatImage truth = clamped(pt.radiance());
  opt.seed = 1;
  pt.setOptions(opt);
  std::vector<double> ms;
  for (int i = 0; i < o.cinematicSpp; ++i) {
    double before = pt.progress().seconds;
    pt.accumulate(p, 1, img);
    ms.push_back((pt.progress().seconds - before) * 1e3);
    check(cancel);
  }
  m.msPerFrame = median(ms);
  m.samples = pt.progress().samples;
  ImageError e = compareImages(clamped(pt.radiance()), truth);
  m.psnrDb = e.psnrDb;
  m.ssim = e.ssim;
  m.referenceSamples = o.cinematicReferenceSpp;
  m.reference = "its own image at " + std::to_string(o.cinematicReferenceSpp) +
                " samples per pixel (another seed; its noise lowers the PSNR by about " +
                "10 log10(1 + " + std::to_string(o.cinematicSpp) + "/" +
                std::to_string(o.cinematicReferenceSpp) + ") dB)";
  return m;
}

}  // namespace

std::vector<LightingMeasurement> measureLighting(ClContext& ctx, const Volume& v,
                                                 const RenderParams& view,
                                                 const LightingMeasureOptions& o,
                                                 const std::atomic<bool>* cancel) {
  if (o.width < 16 || o.height < 16 || o.width > 4096 || o.height > 4096)
    throw inputError("the lighting measurement's size must be 16 to 4096 pixels a side");
  if (!(o.referenceStepVoxels > 0.0) || !(o.rayStepVoxels > 0.0) || o.referenceSamples < 2 ||
      o.cinematicSpp < 1 || o.cinematicReferenceSpp < 2)
    throw inputError(
        "the lighting measurement needs positive reference steps, at least 2 reference "
        "samples and 1 cinematic sample");
  RenderParams p = view;
  p.width = o.width;
  p.height = o.height;
  Raycaster rc(ctx, v);
  std::vector<LightingMeasurement> out;
  for (Lighting l : o.models) {
    check(cancel);
    p.lighting = l;
    out.push_back(l == Lighting::Cinematic ? measureCinematic(rc, p, o, cancel)
                                           : measureGridModel(rc, v, p, o, cancel));
  }
  return out;
}

LightingMeasureTask::LightingMeasureTask(std::string device, Callbacks callbacks,
                                         BackgroundTask::Post post)
    : device_(std::move(device)), callbacks_(std::move(callbacks)), task_(std::move(post)) {}

LightingMeasureTask::~LightingMeasureTask() { cancel(); }

void LightingMeasureTask::cancel() {
  ++*generation_;
  *running_ = false;
  task_.cancel();
}

void LightingMeasureTask::start(std::shared_ptr<const Volume> volume, const RenderParams& view,
                                const LightingMeasureOptions& o) {
  cancel();
  task_.wait();
  const int generation = ++*generation_;
  *running_ = true;
  task_.start([this, volume, view, o, generation] {
    auto gen = generation_;
    auto running = running_;
    Callbacks cb = callbacks_;
    auto current = [gen, generation] { return gen->load() == generation; };
    try {
      ClContext ctx(device_);
      auto result = measureLighting(ctx, *volume, view, o, task_.cancelFlag());
      task_.post([cb, result, current, running] {
        if (!current()) return;  // cancelled, or superseded by a later start
        *running = false;
        if (cb.done) cb.done(result);
      });
    } catch (const std::exception& e) {
      std::string message = e.what();
      bool cancelled = isCancellation(e);
      task_.post([cb, message, cancelled, current, running] {
        if (!current()) return;
        *running = false;
        if (!cancelled && cb.failed) cb.failed(message);
      });
    }
  });
}

}  // namespace voxray
