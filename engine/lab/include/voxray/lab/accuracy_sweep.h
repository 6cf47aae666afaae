#pragma once
// The speed/accuracy sweep behind `voxray-cli accuracy`: each case renders on the OpenCL
// device (median time per frame, and once more with the kernel's iso hit points) and
// through the double-precision reference renderer (hit points, normals, samples taken),
// and is scored against ground truth.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "voxray/engine/render_params.h"
#include "voxray/lab/accuracy.h"

namespace voxray {

class ClContext;

struct SweepScene {
  std::string name;                    // e.g. "ml41", "cthead"
  const Volume* volume = nullptr;      // not owned
  std::optional<AnalyticField> truth;  // analytic volumes: exact surface and normal
  RenderParams base;                   // mode, camera, image size, preset
};

struct SweepCase {
  std::string setting;  // e.g. "step=0.5 linear zh r4"
  RenderParams params;
};

struct SweepRow {
  std::string scene, setting;
  Mode mode = Mode::Iso;
  double msPerFrame = 0.0;        // median wall time of the OpenCL frames
  double samplesPerSecond = 0.0;  // volume reads (counted by the reference) / time
  bool hasSurface = false;        // iso on an analytic volume
  SurfaceError surface;           // against the analytic surface and normal
  ErrorStats kernelSurface;       // the OpenCL kernel's own hit points vs the surface
  ErrorStats hitPoint;            // against the same reconstruction marched finely
  ImageError image;               // OpenCL image against the fine reference image
};

struct SweepOptions {
  int frames = 3;                    // timed OpenCL frames per case (median)
  double fineStepVoxels = 1.0 / 16;  // the reference images' step (the 1/16)
  int fineRefine = 24;               // bisections of the fine iso reference
  std::function<void(const std::string&)> progress;  // one line per case; may be empty
};

// The sweep for a scene: step 0.125 ... 4 voxels, nearest vs trilinear, the three
// gradient operators, and (iso) refinement 0 ... 8. `reduced` keeps a handful of cases
// (for extra resolutions and shapes).
std::vector<SweepCase> standardCases(const SweepScene& scene, bool reduced = false);
// "step=S VARIANT WxH" for a parameter set: the step relative to the scene's voxel size, the
// kernel variant's name (kernelVariantName).
std::string settingLabel(const RenderParams& p, double minSpacingMm);
// The fine reference of a frame p: its operator with interpolation `interp`, step `stepMm`,
// `refine` bisections, no jitter, opacity correction on (the sweep's reference images, and
// the workstation's lighting measurement).
RenderParams fineParams(RenderParams p, Interp interp, double stepMm, int refine);

std::vector<SweepRow> runSweep(ClContext& ctx, const SweepScene& scene,
                               const std::vector<SweepCase>& cases, const SweepOptions& options);

// Cases on the fastest-for-its-error frontier (lower error and lower time dominate).
std::vector<bool> paretoFront(const std::vector<double>& ms, const std::vector<double>& error);

}  // namespace voxray
