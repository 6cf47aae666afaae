#pragma once
// Holds drag frames at a target frame rate: from the render times of the last few drag
// frames it picks the image scale and ray step of the next ones (3D Slicer's adaptive mode
// does the same, and oscillates). Qt-free so that it is tested on synthetic timings.
//
// The cost of a frame is taken as proportional to scale^2 / step (rays times samples per
// ray). The scale goes down first (to minScale), then the step grows (to maxStepFactor
// times the drag preset's). Every `window` frames rendered with the current setting, the
// mean time of the middle half of the last few windows' frames (robust to a stray slow
// frame) is compared with the target: a miss beyond
// `bigMiss` changes the setting at once (a resized view, another volume); a miss beyond
// `band` must persist for `strikes` windows. A change aims at the target exactly, and one
// made on few frames is re-aimed once on more, so that noise cannot start a swing.
#include <vector>

#include "no_qt.h"

namespace voxray {

struct DragSetting {
  double scale = 0.5;       // image size factor of a drag frame
  double stepVoxels = 2.0;  // ray step in units of the smallest voxel spacing
};

struct AdaptiveLimits {
  double minScale = 0.25, maxScale = 1.0;
  double maxStepFactor = 2.0;  // the step grows at most to this times the start step
  int window = 6;              // frames measured before a decision
  int strikes = 3;             // windows a small miss must last
  int history = 5;             // windows of frames the measure keeps (at least `strikes`)
  double band = 0.15;          // relative miss of the target fps tolerated
  double bigMiss = 0.35;       // a miss acted on at once
  double reaim = 0.03;         // the one re-aim after a change corrects misses beyond this
};

class AdaptiveQuality {
 public:
  // START: the drag preset's scale and step (the step also the finest the controller uses).
  AdaptiveQuality(double targetFps, DragSetting start, AdaptiveLimits limits = {});

  // Takes effect at the next decision; values below 1 fps count as 1.
  void setTargetFps(double fps);
  double targetFps() const { return targetFps_; }
  // A drag frame rendered with USED took MS. Frames of an earlier setting (still in
  // flight when it changed) are ignored.
  void record(double ms, const DragSetting& used);
  // What the next drag frame uses.
  const DragSetting& setting() const { return setting_; }
  // How many times the setting has changed (tests: no oscillation).
  int changes() const { return changes_; }

 private:
  DragSetting fromWork(double work) const;  // relative cost scale^2 * baseStep / step
  double work(const DragSetting& s) const;

  double targetFps_;
  double baseStep_;
  AdaptiveLimits limits_;
  DragSetting setting_;
  void change(double miss, bool fewFrames);

  std::vector<double> recent_;  // ms of frames with the current setting, oldest first
  int strikeCount_ = 0;
  bool reaimDue_ = true;  // the start setting is a guess
  int changes_ = 0;
};

}  // namespace voxray
