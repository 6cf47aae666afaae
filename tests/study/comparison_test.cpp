// Compare (issue 36): two columns linked in patient coordinates through a rigid transform,
// and the point-pair alignment that finds it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "comparison_model.h"
#include "point_alignment.h"
#include "rigid_motion.h"
#include "session.h"
#include "slice_geometry.h"
#include "voxray/io/error.h"

namespace voxray {
namespace {

using test::rigid;
using test::rotation;

// Today's CT: 96 x 96 x 48 voxels of 0.9 x 0.9 x 2 mm, centred near the patient origin.
VolumeGeometry fixedGeometry() {
  VolumeGeometry g;
  g.dims = {96, 96, 48};
  g.spacingMm = {0.9, 0.9, 2.0};
  g.originMm = -g.spacingMm * (0.5 * glm::dvec3(g.dims - 1));
  g.frameOfReferenceUid = "1.2.today";
  return g;
}

// The prior: 1 mm isotropic, its own grid turned (patient lay otherwise) and a different
// Frame of Reference; the transform below puts it on today's.
VolumeGeometry movingGeometry() {
  VolumeGeometry g;
  g.dims = {90, 90, 90};
  g.spacingMm = glm::dvec3(1.0);
  g.direction = rotation({0.2, 1.0, -0.3}, 9.0);
  g.originMm = glm::dvec3(-6.0, 4.0, 3.0) - g.direction * (0.5 * glm::dvec3(g.dims - 1));
  g.frameOfReferenceUid = "1.2.prior";
  return g;
}

const glm::dmat4 kMovingToFixed = rigid(rotation({1.0, -0.4, 0.7}, 12.5), {-5.5, 3.25, 2.0});

// The follower's crosshair against where the leader's point lies in its voxels, mapped here
// through kMovingToFixed itself (not the model's mapping): within half a voxel on each axis
// (each column rounds to its own voxel centres).
double followerError(const ComparisonModel& m, const CrosshairModel& fixed,
                     const CrosshairModel& moving, ComparisonModel::Side follower) {
  const glm::dvec3 fixedMm = m.fixed().patientOf(fixed.centre());
  const glm::dvec3 movingMm = m.moving().patientOf(moving.centre());
  const glm::dvec3 d =
      follower == ComparisonModel::Side::Moving
          ? m.moving().voxelOf(
                glm::dvec3(glm::inverse(kMovingToFixed) * glm::dvec4(fixedMm, 1.0))) -
                moving.centre()
          : m.fixed().voxelOf(glm::dvec3(kMovingToFixed * glm::dvec4(movingMm, 1.0))) -
                fixed.centre();
  return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
}

TEST(Comparison, SameLpsPointUnderBothCrosshairsAfterFiftyRandomSteps) {
  ComparisonModel m;
  m.setGeometries(fixedGeometry(), movingGeometry());
  EXPECT_FALSE(m.linked());  // different Frames of Reference: not until aligned
  m.setMovingToFixed(kMovingToFixed);
  ASSERT_TRUE(m.linked());
  CrosshairModel fixed, moving;
  fixed.setGeometry(m.fixed().dims, m.fixed().spacingMm, m.fixed().direction);
  moving.setGeometry(m.moving().dims, m.moving().spacingMm, m.moving().direction);
  ComparisonLink link(m, fixed, moving);
  link.syncMovingToFixed();

  std::mt19937 rng(36);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 2), orient(0, 2), steps(-3, 3);
  const glm::dvec3 centreMm = m.fixed().patientOf(0.5 * glm::dvec3(m.fixed().dims - 1));
  int checked = 0;
  for (int step = 0; step < 50; ++step) {
    const bool fixedLeads = step % 2 == 0 ? true : unit(rng) > 0.0;
    CrosshairModel& leader = fixedLeads ? fixed : moving;
    const VolumeGeometry& g = fixedLeads ? m.fixed() : m.moving();
    const glm::dmat4 toLeader = fixedLeads ? glm::dmat4(1.0) : glm::inverse(kMovingToFixed);
    const SliceAxes axes = sliceAxes(g.direction, Orientation(orient(rng)));
    // Scroll while the crosshair is well inside both volumes (within 30 mm of today's centre;
    // both reach over 40 mm from it); otherwise click or jump back into that region.
    const glm::dvec3 nowMm = m.fixed().patientOf(fixed.centre());
    int what = kind(rng);
    if (glm::length(nowMm - centreMm) > 30.0) what = what == 2 ? 0 : what;
    if (what == 2) {
      leader.scrollView(axes, steps(rng) == 0 ? 1 : steps(rng));
    } else {
      // A random target in a 25 mm ball about today's centre, in the leader's voxels.
      glm::dvec3 offset(unit(rng), unit(rng), unit(rng));
      if (glm::length(offset) > 1.0) offset /= glm::length(offset);
      const glm::dvec3 targetMm = centreMm + 25.0 * offset;
      const glm::dvec3 voxel = g.voxelOf(glm::dvec3(toLeader * glm::dvec4(targetMm, 1.0)));
      if (what == 0) {
        const glm::dvec2 uv = voxelToSlice(axes, g.dims, voxel);
        leader.clickInView(axes, uv.x, uv.y);
      } else {
        leader.setVoxel(glm::ivec3(glm::round(voxel)));
      }
    }
    ASSERT_TRUE(link.lastFollower()) << step;
    const double e = followerError(m, fixed, moving, *link.lastFollower());
    EXPECT_LE(e, 0.5 + 1e-9) << "step " << step;
    ++checked;
  }
  EXPECT_EQ(checked, 50);
  // And in millimetres: the two crosshairs' patient points (the prior's mapped onto today's)
  // lie within half a voxel diagonal of the follower (at most 0.5 * sqrt(0.9^2+0.9^2+2^2)).
  const glm::dvec3 a = m.fixed().patientOf(fixed.centre());
  const glm::dvec3 b(kMovingToFixed * glm::dvec4(m.moving().patientOf(moving.centre()), 1.0));
  EXPECT_LE(glm::length(a - b), 0.5 * std::sqrt(0.81 + 0.81 + 4.0) + 1e-9);
}

TEST(Comparison, SharedFrameOfReferenceLinksWithoutAlignmentAndUnlinkStopsFollowing) {
  ComparisonModel m;
  VolumeGeometry f = fixedGeometry(), g = movingGeometry();
  g.frameOfReferenceUid = f.frameOfReferenceUid;
  m.setGeometries(f, g);
  EXPECT_TRUE(m.linked());
  EXPECT_EQ(m.linkText(), "linked: one Frame of Reference");
  CrosshairModel fixed, moving;
  fixed.setGeometry(f.dims, f.spacingMm, f.direction);
  moving.setGeometry(g.dims, g.spacingMm, g.direction);
  ComparisonLink link(m, fixed, moving);
  fixed.setVoxel({40, 50, 20});
  // Identity transform: the same patient point.
  const glm::dvec3 d = g.patientOf(moving.centre()) - f.patientOf(fixed.centre());
  EXPECT_LE(glm::length(d), 0.5 * std::sqrt(3.0) + 1e-9);  // half the prior's 1 mm voxel diagonal
  m.setLinkWanted(false);
  const glm::dvec3 before = moving.centre();
  fixed.setVoxel({10, 10, 5});
  EXPECT_EQ(moving.centre(), before);
  EXPECT_NE(m.linkText().find("unlinked"), std::string::npos);
}

TEST(Comparison, WindowLevelFollowsOnlyWhileLinked) {
  ComparisonModel m;
  m.setGeometries(fixedGeometry(), movingGeometry());
  CrosshairModel fixed, moving;
  WindowLevelModel fwl, mwl;
  ComparisonLink link(m, fixed, moving, &fwl, &mwl);
  fwl.set({1500.0, 300.0});
  EXPECT_EQ(mwl.value().width, 1500.0);
  EXPECT_EQ(mwl.value().level, 300.0);
  mwl.set({80.0, 35.0});
  EXPECT_EQ(fwl.value().width, 80.0);
  m.setWindowLevelLinked(false);
  fwl.set({400.0, 40.0});
  EXPECT_EQ(mwl.value().width, 80.0);
}

// Five landmarks (LPS mm) spread over a head-sized box.
std::vector<glm::dvec3> landmarks() {
  return {{-60.0, 12.0, 30.0},
          {55.0, -8.0, 22.5},
          {4.0, 70.0, -15.0},
          {-9.5, -66.0, 41.0},
          {18.0, 25.0, -58.0}};
}

double angleDegrees(const glm::dmat3& a, const glm::dmat3& b) {
  const glm::dmat3 d = glm::transpose(a) * b;
  const double c = std::clamp((d[0][0] + d[1][1] + d[2][2] - 1.0) / 2.0, -1.0, 1.0);
  return glm::degrees(std::acos(c));
}

TEST(PointAlignment, RecoversAKnownRotationAndTranslation) {
  const glm::dmat4 truth = rigid(rotation({0.3, -0.5, 0.8}, 17.3), {12.5, -7.25, 30.0});
  const std::vector<glm::dvec3> moving = landmarks();
  std::vector<glm::dvec3> fixed;
  for (const glm::dvec3& p : moving) fixed.emplace_back(truth * glm::dvec4(p, 1.0));
  const RigidAlignment a = alignPointPairs(fixed, moving);
  EXPECT_LE(angleDegrees(glm::dmat3(a.movingToFixed), glm::dmat3(truth)), 0.01);
  EXPECT_LE(glm::length(glm::dvec3(a.movingToFixed[3]) - glm::dvec3(truth[3])), 0.01);
  EXPECT_LE(a.rmsMm, 1e-9);
  EXPECT_TRUE(isRigid(a.movingToFixed));

  // Three pairs are enough; a reflection is never returned (det +1).
  const RigidAlignment three =
      alignPointPairs({fixed.begin(), fixed.begin() + 3}, {moving.begin(), moving.begin() + 3});
  EXPECT_LE(angleDegrees(glm::dmat3(three.movingToFixed), glm::dmat3(truth)), 0.01);
  EXPECT_NEAR(glm::determinant(glm::dmat3(three.movingToFixed)), 1.0, 1e-12);
}

TEST(PointAlignment, ResidualIsTheRmsOfTheMisplacedPairs) {
  const std::vector<glm::dvec3> moving = landmarks();
  std::vector<glm::dvec3> fixed = moving;
  fixed[0] += glm::dvec3(2.0, 0.0, 0.0);  // one landmark placed 2 mm off
  const RigidAlignment a = alignPointPairs(fixed, moving);
  double sum = 0.0;
  for (size_t i = 0; i < fixed.size(); ++i) {
    const double e =
        glm::length(glm::dvec3(a.movingToFixed * glm::dvec4(moving[i], 1.0)) - fixed[i]);
    EXPECT_NEAR(a.residualsMm[i], e, 1e-12);
    sum += e * e;
  }
  EXPECT_NEAR(a.rmsMm, std::sqrt(sum / 5.0), 1e-12);
  // The fit spreads the 2 mm error: the RMS is above 0 and below the 2 mm / sqrt(5) of no fit.
  EXPECT_GT(a.rmsMm, 0.1);
  EXPECT_LT(a.rmsMm, 2.0 / std::sqrt(5.0));
  EXPECT_EQ(formatAlignment(a).substr(0, 4), "RMS ");
}

TEST(PointAlignment, FewerThanThreeOrCollinearPairsAreRefusedWithAMessage) {
  const std::vector<glm::dvec3> two{{0, 0, 0}, {10, 0, 0}};
  try {
    alignPointPairs(two, two);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("at least three point pairs"), std::string::npos)
        << e.what();
  }
  const std::vector<glm::dvec3> line{{0, 0, 0}, {10, 5, 0}, {20, 10, 0}, {-7, -3.5, 0}};
  try {
    alignPointPairs(line, line);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("on one line"), std::string::npos) << e.what();
  }
  EXPECT_THROW(alignPointPairs(landmarks(), two), Error);  // counts differ

  // Through the model: refused, nothing changes.
  ComparisonModel m;
  m.setGeometries(fixedGeometry(), movingGeometry());
  m.addPair({0, 0, 0}, {1, 1, 1});
  m.addPair({10, 0, 0}, {11, 1, 1});
  EXPECT_THROW(m.align(), Error);
  EXPECT_FALSE(m.aligned());
  EXPECT_FALSE(m.linked());
  EXPECT_THROW(m.setMovingToFixed(glm::dmat4(2.0)), Error);  // a scale is no rigid transform
  EXPECT_FALSE(m.aligned());
}

TEST(Comparison, AlignByPairsLinksAndSwapInvertsTheTransform) {
  ComparisonModel m;
  m.setGeometries(fixedGeometry(), movingGeometry());
  for (const glm::dvec3& p : landmarks())
    m.addPair(glm::dvec3(kMovingToFixed * glm::dvec4(p, 1.0)), p);
  const RigidAlignment& a = m.align();
  EXPECT_LE(a.rmsMm, 1e-9);
  EXPECT_TRUE(m.linked());
  const glm::dvec3 v(30.0, 40.0, 20.0);
  const glm::dvec3 w = m.fixedToMovingVoxel(v);
  EXPECT_LE(glm::length(m.movingToFixedVoxel(w) - v), 1e-9);
  m.swap();
  EXPECT_EQ(m.fixed().frameOfReferenceUid, "1.2.prior");
  EXPECT_LE(glm::length(m.movingToFixedVoxel(v) - w), 1e-9);  // the same pair, sides traded
}

TEST(Comparison, SessionKeepsThePriorAndItsTransformAndRefusesANonRigidOne) {
  Session s;
  s.comparison = Session::Comparison{"/data/prior", kMovingToFixed};
  const std::string json = sessionToJson(s, "/tmp/compare-session.json");
  const SessionRead r = sessionFromJson(json, "/tmp/compare-session.json");
  ASSERT_TRUE(r.session.comparison);
  EXPECT_EQ(r.session.comparison->priorPath, "/data/prior");
  ASSERT_TRUE(r.session.comparison->movingToFixed);
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)  // written with JSON's shortest round-trip doubles
      EXPECT_EQ((*r.session.comparison->movingToFixed)[c][row], kMovingToFixed[c][row]);
  EXPECT_TRUE(r.warnings.empty());

  glm::dmat4 scaled = kMovingToFixed;
  scaled[0] *= 1.01;  // 1 % longer along one axis: no rigid transform
  s.comparison->movingToFixed = scaled;
  try {
    sessionFromJson(sessionToJson(s, "/tmp/compare-session.json"), "/tmp/compare-session.json");
    FAIL() << "a scaled transform was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("comparison.moving-to-fixed"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("not rigid"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace voxray
