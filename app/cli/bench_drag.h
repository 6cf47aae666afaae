#pragma once
// voxray-cli bench --drag: a drag of the 3D view replayed on one thread with real frames
// (issue 16's "drag frames >= 20 fps"). Each frame is planned as the render scheduler plans
// it (planFrame with the AdaptiveQuality controller's setting) and its render time goes
// back to the controller as the scheduler's does, so the figures are what the workstation's
// drag does on this machine: the image scales and steps the controller chose, and the frame
// times once it had adapted (its first change: the drag preset's own frames missed).
// A clip drag (`--drag clip`) is replayed the same way with the camera still: one face of the
// clip box moves in and back out, as the 3D view's handle drag moves it (issue 41 item 3).
#include <string>
#include <vector>

#include "voxray/engine/orbit.h"
#include "voxray/engine/raycaster.h"

namespace voxray::cli {

// What a drag moves: the camera round the orbit, or the clip box's anterior face (j low).
enum class DragMotion { Rotation, ClipFace };

// --drag N (a rotation of N frames), --drag clip (a clip drag of kClipDragFrames frames) or
// --drag clip:N. Throws Input naming the option.
struct DragOption {
  static constexpr int kClipDragFrames = 90;
  int frames = 0;
  DragMotion motion = DragMotion::Rotation;
};
DragOption parseDragOption(const std::string& text);

// The clip box of a clip drag's frame I of FRAMES: the anterior face (2: j low) moves from
// the box's edge to half the volume and back, 2 % steps of the extent on a 50-frame pass.
ClipBox clipDragBox(int i, int frames);

struct DragChange {
  int frame = 0;  // the frame whose time made it
  double scale = 0, stepVoxels = 0;
};

// A drag frame lit through the light grid held from the drag's start (Raycaster::
// holdLightGrid) against the same frame with the grid rebuilt for its own light (what the
// frame converges to on release), and the same frame in phong (no shadows at all) against it.
struct HeldGridError {
  double degrees = 0;  // the camera's (and the light's) turn since the grid was built
  double psnrDb = 0, phongPsnrDb = 0;
};

struct DragReplay {
  std::vector<double> ms;        // each drag frame's time, 2-degree steps of the orbit
  std::vector<int> widths;       // and its width
  std::vector<DragChange> path;  // the controller's changes, in order
  // The empty-space occupancy's (re)classifications during the drag (Raycaster::
  // classifications): 0 when the tables were not rebuilt for any move.
  int classifications = 0;
  // Lighting shadows or ao: the light grid's builds after the first frame (0 when the grid
  // held through the drag), each frame's time again in phong at the same setting (rendered
  // right after it, so that both see the same load) and the held grid's error.
  int lightingBuilds = 0;
  std::vector<double> phongMs;
  std::vector<HeldGridError> heldErrors;
  DragMotion motion = DragMotion::Rotation;
  // The first frame rendered with the controller's own setting (0 when it never changed:
  // then every frame counts as adapted).
  size_t firstAdapted() const { return path.empty() ? 0 : size_t(path.front().frame) + 1; }
};

// Renders FRAMES drag frames of BASE in a view of VIEW pixels toward TARGETFPS: the camera
// round ORBIT, or (DragMotion::ClipFace) the clip box by clipDragBox with the camera still.
// With lighting shadows or ao the light grid is held through the drag as the workstation
// holds it, each frame is timed in phong too, and (a rotation with shadows) the held grid's
// error is measured after the timed frames, 10, 30 and 44 degrees into the drag; RC is left
// released.
DragReplay replayDrag(Raycaster& rc, const RenderParams& base, const glm::ivec2& view,
                      double minSpacingMm, Orbit orbit, int frames, double targetFps,
                      DragMotion motion = DragMotion::Rotation);

void printDragReplay(const DragReplay& d, double targetFps);

}  // namespace voxray::cli
