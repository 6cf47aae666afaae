#include <gtest/gtest.h>

#include <cmath>

#include "test_volumes.h"
#include "voxray/engine/camera.h"

namespace voxray {

namespace {
void expectVec(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}
}  // namespace

TEST(Camera, DefaultIsAnteriorViewWithPatientLeftOnImageRight) {
  Volume v = test::constant({10, 10, 10}, 0);
  RenderParams p;
  ViewGeometry g = makeViewGeometry(v, p);
  expectVec(g.forward, {0, 1, 0});  // looking from anterior (-y) towards posterior
  expectVec(g.right, {1, 0, 0});    // image right = +x = patient left (LPS)
  expectVec(g.up, {0, 0, 1});       // superior up
  EXPECT_LT(g.eye.y, 0.0);
}

TEST(Camera, StandardViewsAndStraightDownIsNotDegenerate) {
  Volume v = test::constant({10, 10, 10}, 0);
  RenderParams p;
  p.camera.azimuthDeg = 90.0;  // from the patient's left
  ViewGeometry g = makeViewGeometry(v, p);
  expectVec(g.forward, {-1, 0, 0});
  expectVec(g.up, {0, 0, 1});
  p.camera.azimuthDeg = 0.0;
  p.camera.elevationDeg = 90.0;  // from above
  g = makeViewGeometry(v, p);
  expectVec(g.forward, {0, 0, -1});
  expectVec(g.right, {1, 0, 0});
  expectVec(g.up, {0, 1, 0});  // posterior at the top of a superior view
}

TEST(Camera, FramingFitsTheBoundingSphereAndRaysAreUnitLength) {
  Volume v = test::constant({100, 50, 20}, 0);
  v.spacingMm = {1.0, 2.0, 5.0};  // physical box 100 x 100 x 100 mm
  RenderParams p;
  p.width = 200;
  p.height = 100;
  ViewGeometry g = makeViewGeometry(v, p);
  double radius = 0.5 * std::sqrt(3.0) * 100.0;
  double halfFov = 15.0 * 3.14159265358979323846 / 180.0;
  EXPECT_NEAR(glm::length(g.eye), 1.05 * radius / std::sin(halfFov), 1e-9);
  glm::dvec3 o, d;
  g.ray(0, 0, p.width, p.height, o, d);
  EXPECT_NEAR(glm::length(d), 1.0, 1e-12);
  // Voxel <-> world: the far corner voxel centre is at +(extent - spacing) / 2 mm.
  expectVec(g.toVoxel({49.5, 49.0, 47.5}), {99, 49, 19}, 1e-9);
}

TEST(Camera, IntersectBoxHandlesAxisParallelAndGrazingRays) {
  glm::dvec3 lo(-0.5), hi(9.5);
  double t0, t1;
  int axis;
  // Exactly parallel to x and y, inside the slab: hits through z.
  ASSERT_TRUE(intersectBox({3, 4, -10}, {0, 0, 1}, lo, hi, t0, t1, axis));
  EXPECT_DOUBLE_EQ(t0, 9.5);
  EXPECT_DOUBLE_EQ(t1, 19.5);
  EXPECT_EQ(axis, 2);
  // Parallel and outside: a miss, no NaN.
  EXPECT_FALSE(intersectBox({3, 10, -10}, {0, 0, 1}, lo, hi, t0, t1, axis));
  // Grazing along a face (o.x == lo.x exactly): inside the closed slab.
  ASSERT_TRUE(intersectBox({-0.5, 4, -10}, {0, 0, 1}, lo, hi, t0, t1, axis));
  // Through a corner exactly.
  ASSERT_TRUE(
      intersectBox({-1.5, -1.5, -1.5}, glm::normalize(glm::dvec3(1)), lo, hi, t0, t1, axis));
  EXPECT_NEAR(t0, std::sqrt(3.0), 1e-12);
  // Eye inside: enters at 0 with no entry face.
  ASSERT_TRUE(intersectBox({5, 5, 5}, {1, 0, 0}, lo, hi, t0, t1, axis));
  EXPECT_EQ(t0, 0.0);
  EXPECT_EQ(axis, -1);
  EXPECT_DOUBLE_EQ(t1, 4.5);
}

}  // namespace voxray
