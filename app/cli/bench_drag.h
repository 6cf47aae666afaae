#pragma once
// voxray-cli bench --drag: a drag of the 3D view replayed on one thread with real frames
// (issue 16's "drag frames >= 20 fps"). Each frame is planned as the render scheduler plans
// it (planFrame with the AdaptiveQuality controller's setting) and its render time goes
// back to the controller as the scheduler's does, so the figures are what the workstation's
// drag does on this machine: the image scales and steps the controller chose, and the frame
// times once it had adapted (its first change: the drag preset's own frames missed).
#include <vector>

#include "voxray/engine/orbit.h"
#include "voxray/engine/raycaster.h"

namespace voxray::cli {

struct DragChange {
  int frame = 0;  // the frame whose time made it
  double scale = 0, stepVoxels = 0;
};

struct DragReplay {
  std::vector<double> ms;        // each drag frame's time, 2-degree steps of the orbit
  std::vector<int> widths;       // and its width
  std::vector<DragChange> path;  // the controller's changes, in order
  // The first frame rendered with the controller's own setting (0 when it never changed:
  // then every frame counts as adapted).
  size_t firstAdapted() const { return path.empty() ? 0 : size_t(path.front().frame) + 1; }
};

// Renders FRAMES drag frames of BASE in a view of VIEW pixels toward TARGETFPS.
DragReplay replayDrag(Raycaster& rc, const RenderParams& base, const glm::ivec2& view,
                      double minSpacingMm, Orbit orbit, int frames, double targetFps);

void printDragReplay(const DragReplay& d, double targetFps);

}  // namespace voxray::cli
