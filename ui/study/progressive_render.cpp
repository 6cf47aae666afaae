#include "progressive_render.h"

#include <cstdio>

namespace voxray {

bool ProgressiveRender::onFrame(const RenderParams&, bool interactive, int samples,
                                double seconds) {
  // Only the path tracer (Raycaster::rendererFor, lighting cinematic) counts path samples:
  // its frames have at least one.
  active_ = samples > 0;
  if (!active_) {
    samples_ = 0;
    seconds_ = 0.0;
    return false;
  }
  if (samples <= samples_) ++restarts_;  // the path tracer started afresh: the frame changed
  samples_ = samples;
  seconds_ = seconds;
  return !interactive && samples < kMaxSamples;
}

std::string ProgressiveRender::statusText() const {
  if (!active_) return "";
  char text[96];
  std::snprintf(text, sizeof text, "cinematic: %d sample%s · %.1f s%s", samples_,
                samples_ == 1 ? "" : "s", seconds_, samples_ >= kMaxSamples ? " (done)" : "");
  return text;
}

}  // namespace voxray
