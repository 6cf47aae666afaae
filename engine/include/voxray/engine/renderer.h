#pragma once
// One frame of a volume into an image, whoever computes it: the raycaster (phong, shadows,
// ao) or the path tracer (cinematic). Raycaster::rendererFor chooses one per frame, so that
// callers do not branch on the lighting model.
#include <string>

#include "voxray/engine/render_params.h"
#include "voxray/io/image.h"

namespace voxray {

struct FrameStats {
  double kernelMs = 0.0;  // from OpenCL profiling events
  double totalMs = 0.0;   // wall time including upload of parameters and read-back
  double samples = 0.0;   // volume samples taken (0 unless RaycasterOptions::countSamples)
  std::string variant;    // the -D options of the kernel that ran
  // shadows, ao: wall time of the light grid's precomputation in this frame (0 when the
  // grid was reused), included in totalMs.
  double lightingMs = 0.0;
  // lighting cinematic (path_tracer.h): samples per pixel accumulated so far, and the
  // seconds they took since the last restart.
  int pathSamples = 0;
  double pathSeconds = 0.0;
  // Image-space adaptive sampling (RenderParams::adaptiveImage): the frame's blocks between
  // lattice pixels and those refined (every pixel marched); 0 and 0 when it was off.
  int adaptiveBlocks = 0;
  int adaptiveRefined = 0;
};

// A still image's budget for a progressive renderer: samples per pixel (0: no limit) or
// seconds (0: no limit); one of the two must be given.
struct StillBudget {
  int samples = 0;
  double seconds = 0.0;
};

class Renderer {
 public:
  virtual ~Renderer() = default;
  // Whether repeated frames of the same parameters refine the image (the path tracer).
  virtual bool progressive() const { return false; }
  // The frame of PARAMS into OUT (reused between frames: no allocation per frame). The path
  // tracer adds one pass of samples per call (restarting when the frame changed) and gives
  // the mean so far.
  virtual void render(const RenderParams& params, Image& out, FrameStats* stats = nullptr) = 0;
  // Only rows [Y0, Y1) (OUT keeps its other rows when it already has the frame's size); the
  // path tracer renders its whole next pass.
  virtual void renderRows(const RenderParams& params, Image& out, int y0, int y1,
                          FrameStats* stats = nullptr) = 0;
  // A still image: one frame; a progressive renderer accumulates afresh to BUDGET (STATS:
  // totalMs and kernelMs its seconds, pathSamples, pathSeconds).
  virtual void renderStill(const RenderParams& params, [[maybe_unused]] const StillBudget& budget,
                           Image& out, FrameStats* stats = nullptr) {
    render(params, out, stats);
  }
  Image render(const RenderParams& params, FrameStats* stats = nullptr) {
    Image out;
    render(params, out, stats);
    return out;
  }
};

}  // namespace voxray
