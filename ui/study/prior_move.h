#pragma once
// Compare (issue 36): aligning the prior by dragging ("Move prior"). A drag in a column's
// slice view moves the prior in that view's plane by the drag in millimetres (the view's
// pixel spacing); a Shift+drag turns it about the crosshair point, across that plane, by the
// angle the pointer swept about the crosshair. In either column the prior moves with the
// pointer relative to what the study shows there: in the study's column (Side::Fixed) the
// prior moves in the study's patient coordinates; in the prior's own column (Side::Moving)
// its image moves against the crosshair. Each drag is one undo step (PriorMoveHistory).
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "comparison_model.h"
#include "no_qt.h"
#include "notifier.h"

namespace voxray {

// A slice view's screen in its column's patient coordinates (LPS mm).
struct ScreenPlane {
  glm::dvec3 rightMm{1.0, 0.0, 0.0};  // one widget pixel to the right, as LPS mm
  glm::dvec3 downMm{0.0, 1.0, 0.0};   // one widget pixel down
  glm::dvec2 pivotPx{0.0};            // the crosshair on screen (widget pixels)
  glm::dvec3 pivotMm{0.0};            // the crosshair, LPS mm
};

// The drag FROM -> TO (widget pixels) as a patient vector in PLANE: each pixel is a pixel
// spacing in mm along the screen's axes.
glm::dvec3 dragMm(const ScreenPlane& plane, const glm::dvec2& fromPx, const glm::dvec2& toPx);
// The angle (radians) the pointer swept about PIVOT from FROM to TO, in screen terms (y down:
// positive is clockwise on screen), in (-pi, pi]; 0 when either point is on the pivot.
double sweptAngle(const glm::dvec2& pivotPx, const glm::dvec2& fromPx, const glm::dvec2& toPx);

// MOVINGTOFIXED after a drag FROM -> TO in SIDE's slice view of PLANE (SIDE's patient
// coordinates): the prior moved by dragMm, or turned by sweptAngle about the crosshair and
// the plane's normal. Both stay rigid.
glm::dmat4 movedPrior(const glm::dmat4& movingToFixed, ComparisonModel::Side side,
                      const ScreenPlane& plane, const glm::dvec2& fromPx, const glm::dvec2& toPx);
glm::dmat4 turnedPrior(const glm::dmat4& movingToFixed, ComparisonModel::Side side,
                       const ScreenPlane& plane, const glm::dvec2& fromPx, const glm::dvec2& toPx);

// Where the prior was placed: the transform and whether it was aligned at all (a drag from
// "not aligned" aligns it; undoing that drag makes it not aligned again).
struct PriorPlacement {
  glm::dmat4 movingToFixed{1.0};
  bool aligned = false;
  static PriorPlacement of(const ComparisonModel& m) { return {m.movingToFixed(), m.aligned()}; }
  void applyTo(ComparisonModel& m) const;
};

// Undo and redo of the prior's drags: one step each.
class PriorMoveHistory {
 public:
  static constexpr size_t kLimit = 100;  // the oldest steps go first
  // A drag starts from BEFORE (call once per drag, before it changes anything).
  void beginDrag(const PriorPlacement& before);
  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  size_t undoCount() const { return undo_.size(); }
  size_t redoCount() const { return redo_.size(); }
  // What to restore, given the placement NOW (it becomes the redo or undo step).
  std::optional<PriorPlacement> undo(const PriorPlacement& now);
  std::optional<PriorPlacement> redo(const PriorPlacement& now);
  void clear();

  // A step was added, taken back or redone, or the steps cleared (Edit → Undo follows it).
  Notifier<> changed;

 private:
  std::vector<PriorPlacement> undo_, redo_;
};

}  // namespace voxray
