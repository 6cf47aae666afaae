#include "comparison_model.h"

#include <cmath>
#include <utility>

#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

VolumeGeometry VolumeGeometry::of(const Volume& v) {
  return {v.dims, v.spacingMm, v.originMm, v.direction, v.study.frameOfReferenceUid};
}

glm::dmat4 VolumeGeometry::voxelToPatient() const {
  glm::dmat4 m(1.0);
  for (int a = 0; a < 3; ++a) m[a] = glm::dvec4(direction[a] * spacingMm[a], 0.0);
  m[3] = glm::dvec4(originMm, 1.0);
  return m;
}

glm::dvec3 VolumeGeometry::patientOf(const glm::dvec3& voxel) const {
  return glm::dvec3(voxelToPatient() * glm::dvec4(voxel, 1.0));
}

glm::dvec3 VolumeGeometry::voxelOf(const glm::dvec3& patientMm) const {
  return glm::dvec3(glm::inverse(voxelToPatient()) * glm::dvec4(patientMm, 1.0));
}

bool isRigid(const glm::dmat4& m) {
  const glm::dmat3 r(m);
  const glm::dmat3 e = glm::transpose(r) * r - glm::dmat3(1.0);
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row)
      if (!(std::abs(e[c][row]) < 1e-6)) return false;  // NaN fails too
  return std::abs(glm::determinant(r) - 1.0) < 1e-6 && m[0][3] == 0.0 && m[1][3] == 0.0 &&
         m[2][3] == 0.0 && m[3][3] == 1.0 && std::isfinite(m[3][0]) && std::isfinite(m[3][1]) &&
         std::isfinite(m[3][2]);
}

void ComparisonModel::setGeometries(const VolumeGeometry& fixed, const VolumeGeometry& moving) {
  fixed_ = fixed;
  moving_ = moving;
  changed.notify();
}

bool ComparisonModel::sameFrameOfReference() const {
  return !fixed_.frameOfReferenceUid.empty() &&
         fixed_.frameOfReferenceUid == moving_.frameOfReferenceUid;
}

void ComparisonModel::setMovingToFixed(const glm::dmat4& m) {
  if (!isRigid(m))
    throw inputError(
        "comparison transform: not a rigid transform (a rotation and a translation); "
        "align the volumes again by point pairs");
  movingToFixed_ = m;
  aligned_ = true;
  changed.notify();
}

void ComparisonModel::clearAlignment() {
  movingToFixed_ = glm::dmat4(1.0);
  aligned_ = false;
  last_.reset();
  changed.notify();
}

void ComparisonModel::setLinkWanted(bool on) {
  if (on == linkWanted_) return;
  linkWanted_ = on;
  changed.notify();
}

void ComparisonModel::setWindowLevelLinked(bool on) {
  if (on == wlLinked_) return;
  wlLinked_ = on;
  changed.notify();
}

std::string ComparisonModel::linkText() const {
  std::string how = aligned_ ? "aligned by the user"
                    : sameFrameOfReference()
                        ? "one Frame of Reference"
                        : "no shared Frame of Reference: not linked until aligned (add three or "
                          "more point pairs, then Align)";
  if (!linkWanted_) return "unlinked by the user (" + how + ")";
  return (linked() ? "linked: " : "") + how;
}

glm::dvec3 ComparisonModel::fixedToMovingVoxel(const glm::dvec3& v) const {
  const glm::dvec3 p = fixed_.patientOf(v);
  return moving_.voxelOf(glm::dvec3(glm::inverse(movingToFixed_) * glm::dvec4(p, 1.0)));
}

glm::dvec3 ComparisonModel::movingToFixedVoxel(const glm::dvec3& v) const {
  const glm::dvec3 p = moving_.patientOf(v);
  return fixed_.voxelOf(glm::dvec3(movingToFixed_ * glm::dvec4(p, 1.0)));
}

void ComparisonModel::addPair(const glm::dvec3& fixedMm, const glm::dvec3& movingMm) {
  fixedPts_.push_back(fixedMm);
  movingPts_.push_back(movingMm);
  changed.notify();
}

void ComparisonModel::clearPairs() {
  fixedPts_.clear();
  movingPts_.clear();
  changed.notify();
}

const RigidAlignment& ComparisonModel::align() {
  RigidAlignment a = alignPointPairs(fixedPts_, movingPts_);  // throws: nothing changes
  last_ = std::move(a);
  movingToFixed_ = last_->movingToFixed;
  aligned_ = true;
  linkWanted_ = true;
  changed.notify();
  return *last_;
}

void ComparisonModel::swap() {
  std::swap(fixed_, moving_);
  movingToFixed_ = glm::inverse(movingToFixed_);
  std::swap(fixedPts_, movingPts_);
  last_.reset();
  changed.notify();
}

ComparisonLink::ComparisonLink(ComparisonModel& model, CrosshairModel& fixed,
                               CrosshairModel& moving, WindowLevelModel* fixedWl,
                               WindowLevelModel* movingWl)
    : model_(model), fixed_(fixed), moving_(moving), fixedWl_(fixedWl), movingWl_(movingWl) {
  fixedConn_ = fixed_.changed.connect([this] { follow(fixed_, moving_, true); });
  movingConn_ = moving_.changed.connect([this] { follow(moving_, fixed_, false); });
  modelConn_ = model_.changed.connect([this] { syncMovingToFixed(); });
  if (fixedWl_ && movingWl_) {
    fixedWlConn_ = fixedWl_->changed.connect([this] { followWl(*fixedWl_, *movingWl_); });
    movingWlConn_ = movingWl_->changed.connect([this] { followWl(*movingWl_, *fixedWl_); });
  }
}

ComparisonLink::~ComparisonLink() {
  fixed_.changed.disconnect(fixedConn_);
  moving_.changed.disconnect(movingConn_);
  model_.changed.disconnect(modelConn_);
  if (fixedWl_ && movingWl_) {
    fixedWl_->changed.disconnect(fixedWlConn_);
    movingWl_->changed.disconnect(movingWlConn_);
  }
}

void ComparisonLink::syncMovingToFixed() { follow(fixed_, moving_, true); }

void ComparisonLink::follow(CrosshairModel& leader, CrosshairModel& follower, bool fixedLeads) {
  if (busy_ || !model_.linked()) return;
  busy_ = true;  // the follower's change must not move the leader back (rounding would drift)
  const glm::dvec3 to = fixedLeads ? model_.fixedToMovingVoxel(leader.centre())
                                   : model_.movingToFixedVoxel(leader.centre());
  std::array<glm::dmat3, 3> rotations;
  for (size_t o = 0; o < rotations.size(); ++o) rotations[o] = follower.rotation(Orientation(o));
  follower.setPlanes(to, rotations);
  follower_ = fixedLeads ? ComparisonModel::Side::Moving : ComparisonModel::Side::Fixed;
  busy_ = false;
}

void ComparisonLink::followWl(WindowLevelModel& leader, WindowLevelModel& follower) {
  if (busy_ || !model_.windowLevelLinked()) return;
  busy_ = true;
  follower.set(leader.value());
  busy_ = false;
}

}  // namespace voxray
