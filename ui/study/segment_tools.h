#pragma once
// The segment editor's tools in the slice views, Qt-free: which tool is chosen and its
// settings (brush radius, threshold range, connectivity, the segment they edit), and what a
// click, a drag or a button runs on the SegmentationModel. The operations are voxray/io's
// (segment_edit.h, segment_ops.h, segment_recipe.h), the ones voxray-cli segment runs.
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "notifier.h"
#include "segmentation_model.h"
#include "voxray/engine/render_params.h"
#include "window_level.h"

namespace voxray {

// Scissors works in the 3D view: a lasso removes what lies behind it (segment_scissors.h).
enum class SegmentTool { None, Threshold, Paint, Erase, Seed, Scissors };

struct SegmentToolSettings {
  SegmentTool tool = SegmentTool::None;
  uint8_t label = 0;      // the segment the tools edit (0: none chosen)
  double radiusMm = 5.0;  // paint and erase
  bool sphere = false;    // paint and erase in 3D (a ball) instead of the view's slice (a disc)
  HuRange range{200.0, 3000.0};  // threshold and seeded region, physical values (HU)
  Connectivity connectivity = Connectivity::Faces6;
  bool overwriteOthers = false;  // painting and thresholds take other segments' voxels too
  bool scissorsKeep = false;     // the 3D lasso keeps only what lies behind it (else removes it)
  bool operator==(const SegmentToolSettings& o) const {
    return tool == o.tool && label == o.label && radiusMm == o.radiusMm && sphere == o.sphere &&
           range.lo == o.range.lo && range.hi == o.range.hi && connectivity == o.connectivity &&
           overwriteOthers == o.overwriteOthers && scissorsKeep == o.scissorsKeep;
  }
};

class SegmentToolModel {
 public:
  const SegmentToolSettings& settings() const { return s_; }
  void set(const SegmentToolSettings& s) {
    if (s == s_) return;
    s_ = s;
    changed.notify();
  }
  Notifier<> changed;

 private:
  SegmentToolSettings s_;
};

// The threshold's starting range: the window's (level - width/2 ... level + width/2), what the
// user sees as not black nor white.
HuRange rangeFromWindow(const WindowLevel& wl);

// The threshold's range from what the 3D view shows: iso, its surface's range (isoLo ... isoHi);
// otherwise the render table's opaque range, from the last HU of opacity 0 before the first
// opaque point to the first HU of opacity 0 after the last one (the table is linear between
// points, so every HU strictly between is opaque). A table opaque at an end is opaque beyond
// it (constant): that side is VALUES' (the volume's) end. Clamped to VALUES. Throws an input
// Error when the table is transparent everywhere.
HuRange rangeFromTransferFunction(const RenderParams& p, HuRange values);

// Voxels of the threshold in one slice (axis 0 = i, 1 = j, 2 = k): the preview's count.
size_t previewCount(const Volume& v, int axis, int slice, HuRange range);

// voxray-cli segment --threshold LO,HI [--seed I:J:K --connectivity C]: the recipes of the
// threshold's Apply and of a seeded-region click.
SegmentRecipe thresholdRecipe(HuRange range);
SegmentRecipe seedRecipe(HuRange range, glm::ivec3 seed, Connectivity c);

// The voxel a click at a fractional voxel position seeds: the one whose centre is nearest.
glm::ivec3 nearestVoxel(glm::dvec3 voxel);

// One dab of the paint or erase brush at VOXEL (fractional index) into settings.label; the
// disc lies in the slice across AXIS. Throws an input Error when no segment is chosen.
void brushDab(SegmentationModel& m, const SegmentToolSettings& s, int axis, glm::dvec3 voxel);

// A seeded-region click at SEED: the region of the range connected to it becomes the chosen
// segment's voxels (setMask, as voxray-cli segment --seed writes them). Throws an input Error
// when no segment is chosen or the seed's own value is outside the range.
void seedClick(SegmentationModel& m, const Volume& v, const SegmentToolSettings& s,
               glm::ivec3 seed);
// The threshold's Apply: every voxel in the range becomes the chosen segment's.
void applyThreshold(SegmentationModel& m, const Volume& v, const SegmentToolSettings& s);

// The 3D view's mask (RenderParams::segmentMask) as a choice per segment: shown only,
// hidden, or neither. Show and Hide exclude each other: choosing one for a segment drops the
// other kind's choices.
enum class MaskChoice { Off, ShowOnly, Hide };
MaskChoice maskChoiceOf(const SegmentMask& m, int label);
SegmentMask withMaskChoice(SegmentMask m, int label, MaskChoice c);

// The segment a 3D pick hit (voxel position, surface_pick.h): the nearest voxel's label, or,
// where that is background (a surface point lies between a segment's voxel and the outside),
// the label most of its 26 neighbours hold; 0 for none.
uint8_t segmentAt(const Segmentation& s, glm::dvec3 voxel);

// The operations of the editor's buttons on one segment, each one undo step.
enum class MaskOperation { KeepLargest, RemoveSmall, FillHoles, Margin, Median, Closing, Opening };
const char* toString(MaskOperation op);
// VALUE: mm³ (RemoveSmall), mm (Margin: > 0 grows; the smoothing kernels' diameter); unused
// otherwise. Throws an input Error for a label that names no segment or a bad value.
void applyOperation(SegmentationModel& m, uint8_t label, MaskOperation op, double value,
                    Connectivity c);
// TARGET op= OTHER (segment_ops.h's logical); Add moves OTHER's voxels into TARGET.
void applyLogical(SegmentationModel& m, uint8_t target, uint8_t other, LogicalOp op);

}  // namespace voxray
