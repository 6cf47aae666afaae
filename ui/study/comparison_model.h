#pragma once
// Compare (issue 36): a prior (the moving volume, right column) beside today's study (the
// fixed one, left column). Navigation is linked in patient coordinates (LPS mm) when the two
// name one Frame of Reference, or once the user has aligned them (point pairs, or a
// transform from a session): a crosshair moved in one column puts the other's on the same
// patient point, through movingToFixed, a rigid 4x4 map of the moving volume's patient
// coordinates onto the fixed one's. Window/level follows the other column when linked.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "crosshair_model.h"
#include "no_qt.h"
#include "notifier.h"
#include "point_alignment.h"
#include "window_level.h"

namespace voxray {

struct Volume;

// Where a volume's voxels lie in the patient (as Volume has them) and its Frame of Reference.
struct VolumeGeometry {
  glm::ivec3 dims{1};
  glm::dvec3 spacingMm{1.0}, originMm{0.0};
  glm::dmat3 direction{1.0};
  std::string frameOfReferenceUid;
  static VolumeGeometry of(const Volume& v);
  glm::dmat4 voxelToPatient() const;  // voxel centres at integers -> LPS mm
  glm::dvec3 patientOf(const glm::dvec3& voxel) const;
  glm::dvec3 voxelOf(const glm::dvec3& patientMm) const;
};

// True for a rotation (orthonormal, det +1) and translation within 1e-6.
bool isRigid(const glm::dmat4& m);

class ComparisonModel {
 public:
  enum class Side { Fixed, Moving };
  void setGeometries(const VolumeGeometry& fixed, const VolumeGeometry& moving);
  const VolumeGeometry& fixed() const { return fixed_; }
  const VolumeGeometry& moving() const { return moving_; }
  bool sameFrameOfReference() const;

  // The moving volume's patient coordinates onto the fixed one's (identity until aligned).
  const glm::dmat4& movingToFixed() const { return movingToFixed_; }
  bool aligned() const { return aligned_; }
  // A transform from a session or an alignment: throws Error (Input) unless rigid.
  void setMovingToFixed(const glm::dmat4& m);
  void clearAlignment();
  // Navigation follows the other column: a shared Frame of Reference or an alignment, and
  // the user has not unlinked (linkWanted, e.g. to place point pairs column by column).
  bool linked() const { return linkWanted_ && (sameFrameOfReference() || aligned_); }
  bool linkWanted() const { return linkWanted_; }
  void setLinkWanted(bool on);
  bool windowLevelLinked() const { return wlLinked_; }
  void setWindowLevelLinked(bool on);
  // What the status bar says about the link ("linked: one Frame of Reference", ...).
  std::string linkText() const;

  // A voxel position of one column as the other column's voxel position (same patient point).
  glm::dvec3 fixedToMovingVoxel(const glm::dvec3& fixedVoxel) const;
  glm::dvec3 movingToFixedVoxel(const glm::dvec3& movingVoxel) const;

  // Point pairs (LPS mm of each volume) for alignPointPairs.
  void addPair(const glm::dvec3& fixedMm, const glm::dvec3& movingMm);
  void clearPairs();
  const std::vector<glm::dvec3>& fixedPoints() const { return fixedPts_; }
  const std::vector<glm::dvec3>& movingPoints() const { return movingPts_; }
  // Aligns by the pairs (alignPointPairs: throws Error (Input) for too few or collinear
  // pairs, and then nothing changes) and links navigation.
  const RigidAlignment& align();
  const std::optional<RigidAlignment>& lastAlignment() const { return last_; }

  // The columns trade places: the moving volume becomes the fixed one (the transform inverted).
  void swap();

  Notifier<> changed;

 private:
  VolumeGeometry fixed_, moving_;
  glm::dmat4 movingToFixed_{1.0};
  bool aligned_ = false, linkWanted_ = true, wlLinked_ = true;
  std::vector<glm::dvec3> fixedPts_, movingPts_;
  std::optional<RigidAlignment> last_;
};

// Keeps the two columns' crosshairs (and window/level) on one patient point while MODEL says
// they are linked: a change of either moves the other, never echoed back (each column's
// crosshair rounds to its own voxel centres, so the follower is within half a voxel).
class ComparisonLink {
 public:
  ComparisonLink(ComparisonModel& model, CrosshairModel& fixed, CrosshairModel& moving,
                 WindowLevelModel* fixedWl = nullptr, WindowLevelModel* movingWl = nullptr);
  ~ComparisonLink();
  ComparisonLink(const ComparisonLink&) = delete;
  ComparisonLink& operator=(const ComparisonLink&) = delete;
  // The moving column follows the fixed one now (after a new transform or link).
  void syncMovingToFixed();
  // Which column followed the last change (none: nothing followed).
  std::optional<ComparisonModel::Side> lastFollower() const { return follower_; }

 private:
  void follow(CrosshairModel& leader, CrosshairModel& follower, bool fixedLeads);
  void followWl(WindowLevelModel& leader, WindowLevelModel& follower);
  ComparisonModel& model_;
  CrosshairModel &fixed_, &moving_;
  WindowLevelModel *fixedWl_, *movingWl_;
  bool busy_ = false;
  std::optional<ComparisonModel::Side> follower_;
  int fixedConn_ = 0, movingConn_ = 0, modelConn_ = 0, fixedWlConn_ = 0, movingWlConn_ = 0;
};

}  // namespace voxray
