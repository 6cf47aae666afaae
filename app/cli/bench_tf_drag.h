#pragma once
// voxray-cli bench --tf-drag: issue 35's "TF edit -> new full frame" measured as the editor
// causes it. Pairs of frames at a still camera: the table unchanged, then moved by 1 HU (a
// drag of an opacity point moves the table that much or more). The update alone (table bake,
// upload, the empty-space grid classified again) is the moved frame's time minus the still
// one's, medians of the same run, so the machine's load falls on both alike.
#include "voxray/engine/raycaster.h"

namespace voxray::cli {

struct TfDragFigures {
  double stillMs = 0, movedMs = 0;              // medians of totalMs
  double stillKernelMs = 0, movedKernelMs = 0;  // medians of the raycast kernel's time
  int classifications = 0;                      // occupancy classifications in the moved frames
  int pairs = 0;
};

TfDragFigures replayTfDrag(Raycaster& rc, const RenderParams& base, int pairs);

void printTfDrag(const TfDragFigures& f);

}  // namespace voxray::cli
