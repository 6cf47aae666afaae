#pragma once
// Lighting `cinematic` (issue 15): a progressive Monte Carlo path tracer through the
// classified volume, sharing a Raycaster's device volume and frame setup. Each call adds
// samples (paths per pixel) to a float accumulation and returns the mean so far; anything in
// the frame changing (any render parameter: camera, transfer function, light, clip box,
// size) or the options restarts it. The model (kernels/lighting/path_trace.cl has the details):
//   - extinction per mm sigma = -ln(1 - min(a, opacityCap)) / s, a the transfer function's
//     opacity, which is defined per reference step s (the smallest voxel spacing, as dvr's
//     opacity correction reads it): a slab of d mm with opacity a has transmittance
//     (1 - a)^(d / s) = exp(-sigma d), as in dvr;
//   - albedo: the transfer function's colour; no emission; isotropic phase function;
//   - delta (Woodcock) tracking against one majorant per frame; next-event estimation of the
//     point light (render params `light`, no distance falloff, irradiance such that an
//     unshadowed scatter of albedo c returns c * `diffuse`) with a ratio-tracked
//     transmittance ray; a uniform environment of radiance `ambient`; camera rays leaving
//     without a scatter show `background`;
//   - at most maxBounces scatters per path (1: single scattering).
// The frame is classified as dvr whatever `mode` says (the table of the preset, or CT-Bone).
// Random numbers are counter-based (kernels/path_rng.h): for a fixed seed and sample count
// the image is the same on a given device, however the samples were split into calls.
#include <cstdint>
#include <memory>

#include "voxray/engine/reference_renderer.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/renderer.h"
#include "voxray/io/image.h"

namespace voxray {

class Raycaster;
struct DeviceFrame;

struct PathTracerOptions {
  uint32_t seed = 1;
  int maxBounces = 4;         // scatters per path, 1 ... 64
  double opacityCap = 0.999;  // keeps sigma finite where the table's opacity is 1
};

struct PathProgress {
  int samples = 0;       // paths per pixel accumulated since the last restart
  double seconds = 0.0;  // time spent accumulating them (kernel and read-back)
};

// The parameters the path tracer classifies and sets up a frame with (mode dvr).
RenderParams cinematicFrame(const RenderParams& p);
// The majorant of a frame: the largest extinction per mm its table can give.
double pathMajorant(const Lut& lut, double referenceStepMm, double opacityCap);

class PathTracer : public Renderer {
 public:
  // Shares the raycaster's device volume, setup and frame buffers (Raycaster::deviceFrame).
  // Not copyable (it owns device buffers).
  explicit PathTracer(Raycaster& raycaster);
  ~PathTracer() override;
  PathTracer(const PathTracer&) = delete;
  PathTracer& operator=(const PathTracer&) = delete;

  bool progressive() const override { return true; }
  using Renderer::render;
  // One pass of one path per pixel (accumulate(P, 1, OUT)), counted in STATS' pathSamples
  // and pathSeconds.
  void render(const RenderParams& p, Image& out, FrameStats* stats = nullptr) override;
  // The whole next pass: paths do not refine in bands.
  void renderRows(const RenderParams& p, Image& out, int y0, int y1,
                  FrameStats* stats = nullptr) override;
  // run(P, BUDGET's samples, its seconds, OUT).
  void renderStill(const RenderParams& p, const StillBudget& budget, Image& out,
                   FrameStats* stats = nullptr) override;

  // Adds `samples` paths per pixel in one kernel launch (restarting first when the frame
  // changed) and writes the mean so far into out (8-bit, clamped like render()).
  PathProgress accumulate(const RenderParams& p, int samples, Image& out);
  // Accumulates until `samples` per pixel (0: no limit) or `seconds` (0: no limit; one of the
  // two must be given) in launches of at most maxPassSeconds each, sized from the last.
  PathProgress run(const RenderParams& p, int samples, double seconds, Image& out,
                   double maxPassSeconds = 1.0);
  PathProgress progress() const;
  void restart();
  void setOptions(const PathTracerOptions& options);  // restarts; throws Error (Input)
  const PathTracerOptions& options() const;
  // The mean radiance per pixel so far, linear RGB before clamping (measurements, tests).
  FloatImage radiance() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace voxray
