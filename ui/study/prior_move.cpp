#include "prior_move.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace voxray {

glm::dvec3 dragMm(const ScreenPlane& plane, const glm::dvec2& fromPx, const glm::dvec2& toPx) {
  const glm::dvec2 d = toPx - fromPx;
  return d.x * plane.rightMm + d.y * plane.downMm;
}

double sweptAngle(const glm::dvec2& pivot, const glm::dvec2& fromPx, const glm::dvec2& toPx) {
  const glm::dvec2 a = fromPx - pivot, b = toPx - pivot;
  if (a == glm::dvec2(0.0) || b == glm::dvec2(0.0)) return 0.0;
  return std::atan2(a.x * b.y - a.y * b.x, glm::dot(a, b));
}

namespace {
glm::dmat4 translation(const glm::dvec3& d) { return glm::translate(glm::dmat4(1.0), d); }

// Fixed side: the prior moves in the study's coordinates (the change comes first); moving
// side: in its own (the change comes last), so the same drag feels the same in both columns.
glm::dmat4 compose(const glm::dmat4& movingToFixed, ComparisonModel::Side side,
                   const glm::dmat4& change) {
  return side == ComparisonModel::Side::Fixed ? change * movingToFixed : movingToFixed * change;
}
}  // namespace

glm::dmat4 movedPrior(const glm::dmat4& movingToFixed, ComparisonModel::Side side,
                      const ScreenPlane& plane, const glm::dvec2& fromPx, const glm::dvec2& toPx) {
  return compose(movingToFixed, side, translation(dragMm(plane, fromPx, toPx)));
}

glm::dmat4 turnedPrior(const glm::dmat4& movingToFixed, ComparisonModel::Side side,
                       const ScreenPlane& plane, const glm::dvec2& fromPx, const glm::dvec2& toPx) {
  // Turning about cross(right, down) by a positive angle takes the screen's right towards its
  // down: clockwise on screen, as sweptAngle counts.
  const glm::dvec3 axis = glm::normalize(glm::cross(plane.rightMm, plane.downMm));
  const double angle = sweptAngle(plane.pivotPx, fromPx, toPx);
  const glm::dmat4 turn = translation(plane.pivotMm) * glm::rotate(glm::dmat4(1.0), angle, axis) *
                          translation(-plane.pivotMm);
  return compose(movingToFixed, side, turn);
}

void PriorPlacement::applyTo(ComparisonModel& m) const {
  if (aligned)
    m.setMovingToFixed(movingToFixed);
  else
    m.clearAlignment();
}

void PriorMoveHistory::beginDrag(const PriorPlacement& before) {
  undo_.push_back(before);
  if (undo_.size() > kLimit) undo_.erase(undo_.begin());
  redo_.clear();
  changed.notify();
}

std::optional<PriorPlacement> PriorMoveHistory::undo(const PriorPlacement& now) {
  if (undo_.empty()) return std::nullopt;
  const PriorPlacement back = undo_.back();
  undo_.pop_back();
  redo_.push_back(now);
  changed.notify();
  return back;
}

std::optional<PriorPlacement> PriorMoveHistory::redo(const PriorPlacement& now) {
  if (redo_.empty()) return std::nullopt;
  const PriorPlacement next = redo_.back();
  redo_.pop_back();
  undo_.push_back(now);
  changed.notify();
  return next;
}

void PriorMoveHistory::clear() {
  undo_.clear();
  redo_.clear();
  changed.notify();
}

}  // namespace voxray
