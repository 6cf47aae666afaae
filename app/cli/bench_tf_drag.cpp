#include "bench_tf_drag.h"

#include <cstdio>
#include <vector>

#include "voxray/io/statistics.h"

namespace voxray::cli {

TfDragFigures replayTfDrag(Raycaster& rc, const RenderParams& base, int pairs) {
  RenderParams p = base;
  Image image;
  rc.rendererFor(p).render(p, image);  // kernel built, tables made: not an edit
  std::vector<double> still, moved, stillKernel, movedKernel;
  TfDragFigures f;
  f.pairs = pairs;
  for (int i = 0; i < pairs; ++i) {
    FrameStats s;
    rc.rendererFor(p).render(p, image, &s);
    still.push_back(s.totalMs);
    stillKernel.push_back(s.kernelMs);
    // Back and forth by 1 HU, so the table stays where the scene put it.
    p.presetShiftHu = base.presetShiftHu + ((i % 2) == 0 ? 1.0 : 0.0);
    const int before = rc.classifications();
    rc.rendererFor(p).render(p, image, &s);
    f.classifications += rc.classifications() - before;
    moved.push_back(s.totalMs);
    movedKernel.push_back(s.kernelMs);
  }
  f.stillMs = quantile(still, 0.5);
  f.movedMs = quantile(moved, 0.5);
  f.stillKernelMs = quantile(stillKernel, 0.5);
  f.movedKernelMs = quantile(movedKernel, 0.5);
  return f;
}

void printTfDrag(const TfDragFigures& f) {
  std::printf(
      "tf drag: %d pairs at a still camera; table unchanged: median %.2f ms (kernel %.2f); "
      "table moved 1 HU: median %.2f ms (kernel %.2f); the update alone: %.2f ms; the "
      "occupancy grid classified %d times in the moved frames\n",
      f.pairs, f.stillMs, f.stillKernelMs, f.movedMs, f.movedKernelMs, f.movedMs - f.stillMs,
      f.classifications);
  std::fflush(stdout);
}

}  // namespace voxray::cli
