// Compare (issue 36): moving the prior by dragging in a slice view (prior_move.h): a drag's
// millimetres are its pixels times the view's pixel spacing, a Shift+drag's angle is the one
// the pointer swept about the crosshair, each drag is one undo step, and the linked crosshair
// follows the new transform.
#include <gtest/gtest.h>

#include <cmath>

#include "prior_move.h"

#include "rigid_motion.h"

namespace voxray {
namespace {

glm::dmat4 turnAboutZ(double degrees, const glm::dvec3& t) {
  const double a = glm::radians(degrees);
  glm::dmat4 m(glm::dmat3(glm::dvec3(std::cos(a), std::sin(a), 0),
                          glm::dvec3(-std::sin(a), std::cos(a), 0), glm::dvec3(0, 0, 1)));
  m[3] = glm::dvec4(t, 1.0);
  return m;
}

// An axial view at 0.5 mm per widget pixel: screen right is patient left (+x in LPS), screen
// down is posterior (+y), the crosshair at pixel (200, 150) on patient point (10, -20, 35).
ScreenPlane axialPlane() {
  ScreenPlane p;
  p.rightMm = {0.5, 0.0, 0.0};
  p.downMm = {0.0, 0.5, 0.0};
  p.pivotPx = {200.0, 150.0};
  p.pivotMm = {10.0, -20.0, 35.0};
  return p;
}

// The angle (degrees) of the rotation part of M, from its trace.
double rotationDegrees(const glm::dmat4& m) {
  const double c = (m[0][0] + m[1][1] + m[2][2] - 1.0) / 2.0;
  return glm::degrees(std::acos(std::clamp(c, -1.0, 1.0)));
}

TEST(PriorMove, DragOfNPixelsMovesTheTransformByNTimesTheSpacing) {
  const glm::dmat4 before = turnAboutZ(10.0, {3.0, -4.0, 5.0});
  // 37 pixels right and 12 up at 0.5 mm: (18.5, -6, 0) mm, binary fractions: exact.
  const glm::dmat4 moved =
      movedPrior(before, ComparisonModel::Side::Fixed, axialPlane(), {120, 90}, {157, 78});
  EXPECT_EQ(glm::dvec3(moved[3]) - glm::dvec3(before[3]), glm::dvec3(18.5, -6.0, 0.0));
  for (int c = 0; c < 3; ++c) EXPECT_EQ(moved[c], before[c]);  // no turn
  // In the prior's own column the drag is in its coordinates: the same length, turned into
  // today's by the transform's rotation (rounding of one rotation: 1e-12 mm).
  const glm::dmat4 own =
      movedPrior(before, ComparisonModel::Side::Moving, axialPlane(), {120, 90}, {157, 78});
  const glm::dvec3 d = glm::dvec3(own[3]) - glm::dvec3(before[3]);
  EXPECT_NEAR(glm::length(d), std::hypot(18.5, 6.0), 1e-12);
  EXPECT_NEAR(glm::length(d - glm::dmat3(before) * glm::dvec3(18.5, -6.0, 0.0)), 0.0, 1e-12);
  EXPECT_TRUE(isRigid(moved) && isRigid(own));
}

TEST(PriorMove, ShiftDragTurnsByTheAngleThePointerSweptAboutTheCrosshair) {
  const ScreenPlane plane = axialPlane();
  const glm::dvec2 from{260.0, 170.0}, to{190.0, 220.0};
  // The pointer's bearings about the crosshair (screen y down): 18.43 and 101.31 degrees.
  const double expected = glm::degrees(std::atan2(220.0 - 150.0, 190.0 - 200.0) -
                                       std::atan2(170.0 - 150.0, 260.0 - 200.0));
  EXPECT_NEAR(glm::degrees(sweptAngle(plane.pivotPx, from, to)), expected, 1e-12);
  const glm::dmat4 before = turnAboutZ(-6.0, {1.0, 2.0, -3.0});
  const glm::dmat4 after = turnedPrior(before, ComparisonModel::Side::Fixed, plane, from, to);
  ASSERT_TRUE(isRigid(after));
  const glm::dmat4 change = after * glm::inverse(before);
  EXPECT_NEAR(rotationDegrees(change), expected, 1e-9);
  // About the crosshair: it stays put, and about the view's normal (+z here): a point to the
  // crosshair's screen right turns clockwise on screen, towards screen down (+y).
  const glm::dvec3 p = plane.pivotMm, q = plane.pivotMm + glm::dvec3(10.0, 0.0, 0.0);
  EXPECT_NEAR(glm::length(test::applyRigid(change, p) - p), 0.0, 1e-9);
  const double a = glm::radians(expected);
  EXPECT_NEAR(glm::length(test::applyRigid(change, q) -
                          (p + 10.0 * glm::dvec3(std::cos(a), std::sin(a), 0))),
              0.0, 1e-9);
  // In the prior's column the crosshair's point in the prior stays on today's crosshair.
  const glm::dmat4 own = turnedPrior(before, ComparisonModel::Side::Moving, plane, from, to);
  EXPECT_NEAR(glm::length(test::applyRigid(own, p) - test::applyRigid(before, p)), 0.0, 1e-9);
  EXPECT_NEAR(rotationDegrees(own * glm::inverse(before)), expected, 1e-9);
}

TEST(PriorMove, LinkedCrosshairMapsTheSamePointAfterADrag) {
  ComparisonModel m;
  VolumeGeometry f, g;
  f.dims = {64, 64, 40};
  f.spacingMm = {0.5, 0.5, 2.0};
  f.originMm = {-16.0, -40.0, 0.0};
  g.dims = {50, 50, 50};
  g.spacingMm = glm::dvec3(1.0);
  g.originMm = {-30.0, -50.0, -10.0};
  m.setGeometries(f, g);
  CrosshairModel fixed, moving;
  fixed.setGeometry(f.dims, f.spacingMm, f.direction);
  moving.setGeometry(g.dims, g.spacingMm, g.direction);
  ComparisonLink link(m, fixed, moving);
  fixed.setVoxel({30, 20, 18});
  EXPECT_FALSE(m.linked());  // no Frame of Reference: a drag aligns (and links) them
  PriorMoveHistory history;
  history.beginDrag(PriorPlacement::of(m));
  ScreenPlane plane = axialPlane();
  plane.pivotMm = f.patientOf(fixed.centre());
  m.setMovingToFixed(movedPrior(m.movingToFixed(), ComparisonModel::Side::Fixed, plane, {100, 100},
                                {124, 92}));  // 12 mm left, 4 mm anterior
  ASSERT_TRUE(m.linked());
  const glm::dvec3 wanted =
      g.voxelOf(test::applyRigid(glm::inverse(m.movingToFixed()), f.patientOf(fixed.centre())));
  const glm::dvec3 e = glm::abs(moving.centre() - wanted);
  EXPECT_LE(std::max({e.x, e.y, e.z}), 0.5 + 1e-9);  // the prior rounds to its voxel centres
  // The moved prior's point under its crosshair: today's point less the 12 and -4 mm.
  EXPECT_LE(glm::length(g.patientOf(wanted) -
                        (f.patientOf(fixed.centre()) - glm::dvec3(12.0, -4.0, 0.0))),
            1e-9);
  // A turn, then two undos: back to not aligned (and unlinked); redo brings the move back.
  history.beginDrag(PriorPlacement::of(m));
  const glm::dmat4 afterMove = m.movingToFixed();
  m.setMovingToFixed(
      turnedPrior(afterMove, ComparisonModel::Side::Fixed, plane, {150, 150}, {200, 200}));
  EXPECT_EQ(history.undoCount(), 2u);
  history.undo(PriorPlacement::of(m))->applyTo(m);
  EXPECT_EQ(m.movingToFixed(), afterMove);
  history.undo(PriorPlacement::of(m))->applyTo(m);
  EXPECT_FALSE(m.aligned());
  EXPECT_FALSE(m.linked());
  EXPECT_FALSE(history.canUndo());
  history.redo(PriorPlacement::of(m))->applyTo(m);
  EXPECT_EQ(m.movingToFixed(), afterMove);
  EXPECT_TRUE(m.linked());
  EXPECT_TRUE(history.canRedo());
  history.beginDrag(PriorPlacement::of(m));  // a new drag forgets what was undone
  EXPECT_FALSE(history.canRedo());
}

}  // namespace
}  // namespace voxray
