#include "crosshair_model.h"

#include <cmath>

namespace voxray {

void CrosshairModel::setDims(const glm::ivec3& dims) {
  setGeometry(dims, glm::dvec3(1.0), glm::dmat3(1.0));
}

void CrosshairModel::setGeometry(const glm::ivec3& dims, const glm::dvec3& spacingMm,
                                 const glm::dmat3& direction) {
  dims_ = glm::max(dims, glm::ivec3(1));
  spacing_ = spacingMm;
  direction_ = direction;
  rotation_.fill(glm::dmat3(1.0));
  centre_ = glm::dvec3(-1.0);  // forces a notification below
  setVoxel(dims_ / 2);
}

void CrosshairModel::setVoxel(const glm::ivec3& voxel) { moveTo(glm::dvec3(voxel)); }

void CrosshairModel::moveTo(const glm::dvec3& centre) {
  glm::dvec3 clamped = glm::clamp(centre, glm::dvec3(0.0), glm::dvec3(dims_ - 1));
  if (!rotated()) clamped = glm::round(clamped);
  if (clamped == centre_) return;
  centre_ = clamped;
  changed.notify();
}

glm::dmat3 CrosshairModel::voxelToMm() const {
  return direction_ * glm::dmat3(glm::dvec3(spacing_.x, 0, 0), glm::dvec3(0, spacing_.y, 0),
                                 glm::dvec3(0, 0, spacing_.z));
}

glm::dvec3 CrosshairModel::viewToVoxel(const SliceAxes& axes, double u, double v) const {
  const glm::dvec3 base = sliceToVoxel(axes, dims_, u, v, centre_[axes.nAxis]);
  const glm::dmat3& r = rotation(axes.orientation);
  if (isIdentity(r)) return base;
  // The acquisition plane's point turned about the crosshair with the view's plane.
  const glm::dmat3 m = voxelToMm();
  return centre_ + glm::inverse(m) * (r * (m * (base - centre_)));
}

void CrosshairModel::clickInView(const SliceAxes& axes, double u, double v) {
  moveTo(viewToVoxel(axes, u, v));
}

void CrosshairModel::scrollView(const SliceAxes& axes, int steps) {
  if (!rotated()) {
    glm::dvec3 next = centre_;
    next[axes.nAxis] += steps;
    moveTo(next);
    return;
  }
  // One slice spacing along the turned normal.
  const glm::dvec3 normal = frame(axes).normal;
  moveTo(centre_ + glm::inverse(voxelToMm()) * (normal * (steps * spacing_[axes.nAxis])));
}

bool CrosshairModel::rotated() const {
  for (const glm::dmat3& r : rotation_)
    if (!isIdentity(r)) return true;
  return false;
}

PlaneFrame CrosshairModel::frame(const SliceAxes& axes) const {
  return rotateFrame(rotation(axes.orientation), baseFrame(direction_, axes));
}

void CrosshairModel::rotateInView(const SliceAxes& axes, double angleRad) {
  if (angleRad == 0.0 || !std::isfinite(angleRad)) return;
  const PlaneFrame f = frame(axes);
  // Clockwise on a y-down screen is positive about the axis into it, right x down.
  const glm::dmat3 turn = rotationAbout(glm::cross(f.right, f.down), angleRad);
  for (int o = 0; o < 3; ++o)
    if (o != int(axes.orientation))
      rotation_[size_t(o)] = orthonormalised(turn * rotation_[size_t(o)]);
  changed.notify();
}

void CrosshairModel::resetRotation() {
  if (!rotated()) return;
  rotation_.fill(glm::dmat3(1.0));
  centre_ = glm::round(centre_);
  changed.notify();
}

void CrosshairModel::setPlanes(const glm::dvec3& centre,
                               const std::array<glm::dmat3, 3>& rotations) {
  const glm::dvec3 to = centre;  // a copy: CENTRE may be centre() itself, overwritten below
  const bool turned = rotations != rotation_;
  rotation_ = rotations;
  if (turned) centre_ = glm::dvec3(-1.0);  // moveTo notifies even if the centre stays
  moveTo(to);
}

void CrosshairModel::setSlab(Orientation o, const Slab& slab) {
  Slab s = slab;
  if (!(s.thicknessMm > 0.0)) s.thicknessMm = 0.0;  // NaN or negative: a thin slice
  Slab& current = slab_[size_t(o)];
  if (s.thicknessMm == current.thicknessMm && s.mode == current.mode) return;
  current = s;
  changed.notify();
}

}  // namespace voxray
