#pragma once
// Lighting cinematic in the 3D view: each still (not drag) view frame adds one pass of path
// samples (the Raycaster's path tracer restarts itself when anything in the frame changed)
// and asks for the next pass of the same frame, up to a sample budget; the status bar shows
// the samples and seconds so far.
#include <string>

#include "no_qt.h"
#include "voxray/engine/render_params.h"

namespace voxray {

class ProgressiveRender {
 public:
  // 1024 samples: about 10 minutes of a 512x384 CT-Bone view on 2 CPU cores, seconds on a
  // GPU; the image stops changing visibly long before.
  static constexpr int kMaxSamples = 1024;

  // A view frame of P arrived with the path tracer's counts (FrameStats::pathSamples,
  // pathSeconds; 0 from the raycaster, which no pass refines). Returns whether to ask for
  // another pass of the same frame.
  bool onFrame(const RenderParams& p, bool interactive, int samples, double seconds);
  bool active() const { return active_; }  // the last frame was cinematic
  int samples() const { return samples_; }
  double seconds() const { return seconds_; }
  int restarts() const { return restarts_; }  // times the count started again (not the first)
  // "cinematic: 128 samples · 12.3 s" (plus " (done)" at the budget); "" when not cinematic.
  std::string statusText() const;

 private:
  bool active_ = false;
  int samples_ = 0, restarts_ = 0;
  double seconds_ = 0.0;
};

}  // namespace voxray
