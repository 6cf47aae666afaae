#pragma once
// "Measure on this view" (issue 15): each lighting model's cost and error on the view on
// screen, at a small size, in a background task. Error: the kernel's frame against the
// Monte Carlo reference of the same view (monte_carlo_reference.h: phong's is the exact
// reference renderer, shadows' and ao's a stated number of realisations with their standard
// error), the recipe of `voxray-cli accuracy --lighting` (its 1/16-voxel reference step: a
// coarser one still carries step error, 3 dB of ao's on the sphere-on-plane scene at 1/4
// voxel) with twice its realisations; cinematic against its own image at many more samples
// (another seed), as `accuracy --lighting cinematic` does. PSNR and SSIM (lab/accuracy.h).
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "background_task.h"
#include "no_qt.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/volume.h"

namespace voxray {
class ClContext;
}

namespace voxray {

struct LightingMeasureOptions {
  int width = 256, height = 192;
  // The reference's ray step (voxels of the smallest spacing), as the CLI's sweep.
  double referenceStepVoxels = 1.0 / 16;
  double rayStepVoxels = 0.5;  // the reference's shadow and occlusion rays (as the CLI)
  // Monte Carlo realisations of shadows' and ao's reference: the CLI takes 4, whose noise
  // alone lowers ao's PSNR by ~0.9 dB on the sphere-on-plane scene (lighting_figures_test).
  int referenceSamples = 8;
  int frames = 3;                   // timed kernel frames per model (median)
  int cinematicSpp = 16;            // the path tracer's image measured ...
  int cinematicReferenceSpp = 256;  // ... against its own image at this many samples
  std::vector<Lighting> models{Lighting::Phong, Lighting::Shadows, Lighting::Ao,
                               Lighting::Cinematic};
};

// One model on one view.
struct LightingMeasurement {
  Lighting lighting = Lighting::Phong;
  int width = 0, height = 0;
  double msPerFrame = 0.0;    // median kernel frame, the light grid's build left out
                              // (cinematic: per pass of one sample per pixel)
  double precomputeMs = 0.0;  // shadows, ao: one build of the light grid (kernels warm)
  double psnrDb = 0.0, ssim = 0.0;
  int referenceSamples = 0;        // 0: an exact (deterministic) reference
  double referenceStdError = 0.0;  // its mean per-pixel standard error (0 ... 1 scale)
  int samples = 0;                 // cinematic: samples per pixel of the measured image
  std::string reference;           // what the error was measured against, in words
};

// Renders view (its camera, table, light and quality, at o's size) with each of o.models on
// ctx. Throws Error (Cancelled) as soon as it sees *cancel set; Error (Input) for bad options.
std::vector<LightingMeasurement> measureLighting(ClContext& ctx, const Volume& v,
                                                 const RenderParams& view,
                                                 const LightingMeasureOptions& o = {},
                                                 const std::atomic<bool>* cancel = nullptr);

// The measurement as the workstation runs it: one at a time on a thread of its own, with
// an OpenCL context of its own (the render thread's Raycaster is not shared), cancelled
// when the volume changes. Results and errors arrive through the Post.
class LightingMeasureTask {
 public:
  struct Callbacks {
    std::function<void(std::vector<LightingMeasurement>)> done;
    std::function<void(const std::string& message)> failed;  // not for a cancellation
  };
  LightingMeasureTask(std::string device, Callbacks callbacks, BackgroundTask::Post post = {});
  ~LightingMeasureTask();  // cancels and waits

  // Cancels a measurement in progress and starts one of VIEW on VOLUME.
  void start(std::shared_ptr<const Volume> volume, const RenderParams& view,
             const LightingMeasureOptions& o = {});
  // The volume changed: the measurement in progress is dropped (no callback).
  void cancel();
  bool running() const { return running_->load(); }
  void wait() { task_.wait(); }

 private:
  std::string device_;
  Callbacks callbacks_;
  // Shared with the job's events: a cancelled job's late result is recognised and dropped.
  std::shared_ptr<std::atomic<int>> generation_ = std::make_shared<std::atomic<int>>(0);
  std::shared_ptr<std::atomic<bool>> running_ = std::make_shared<std::atomic<bool>>(false);
  BackgroundTask task_;
};

}  // namespace voxray
