// Compare (issue 36): the two columns' 3D cameras linked in patient coordinates (camera_link.h)
// and checked against the engine's own rays (makeViewGeometry): the linked camera shows the
// same patient from the same eye along the same direction, through the alignment transform.
#include <gtest/gtest.h>

#include <cmath>

#include "camera_control.h"
#include "camera_link.h"
#include "rigid_motion.h"
#include "voxray/engine/camera.h"

namespace voxray {
namespace {

using test::rigid;
using test::rotation;

// Today's CT (96 x 96 x 48 of 0.9 x 0.9 x 2 mm) and a prior on a grid of its own (turned,
// 1 mm, elsewhere), as in comparison_test.
VolumeGeometry offsetFixedGeometry() {
  VolumeGeometry g;
  g.dims = {96, 96, 48};
  g.spacingMm = {0.9, 0.9, 2.0};
  g.originMm = -g.spacingMm * (0.5 * glm::dvec3(g.dims - 1)) + glm::dvec3(3.0, -2.0, 10.0);
  g.frameOfReferenceUid = "1.2.today";
  return g;
}
VolumeGeometry unevenMovingGeometry() {
  VolumeGeometry g;
  g.dims = {90, 80, 70};
  g.spacingMm = glm::dvec3(1.0);
  g.direction = rotation({0.2, 1.0, -0.3}, 9.0);
  g.originMm = glm::dvec3(-6.0, 4.0, 3.0) - g.direction * (0.5 * glm::dvec3(g.dims - 1));
  g.frameOfReferenceUid = "1.2.prior";
  return g;
}

// Rounding of a few matrix products on coordinates of ~100 mm: ~1e-13; 1e-9 leaves room.
constexpr double kTol = 1e-9;

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tol, const char* what) {
  EXPECT_LE(glm::length(a - b), tol) << what << ": (" << a.x << ", " << a.y << ", " << a.z
                                     << ") vs (" << b.x << ", " << b.y << ", " << b.z << ")";
}

// Each of a few pixels' rays of CAMERA on G, in patient LPS mm, against the linked camera's
// on H with FROMTOTO applied: the same lines (origins along the ray and directions).
void expectSameRays(const CameraParams& a, const VolumeGeometry& g, const CameraParams& b,
                    const VolumeGeometry& h, const glm::dmat4& fromToTo) {
  const PatientView va = patientView(a, g), vb = patientView(b, h);
  const glm::dvec3 ca = volumeCentreMm(g), cb = volumeCentreMm(h);
  const glm::dmat3 r(fromToTo);
  for (const glm::ivec2 px : {glm::ivec2(0, 0), glm::ivec2(511, 0), glm::ivec2(255, 191),
                              glm::ivec2(37, 380), glm::ivec2(511, 383)}) {
    glm::dvec3 oa, da, ob, db;
    va.engine.ray(px.x, px.y, 512, 384, oa, da);
    vb.engine.ray(px.x, px.y, 512, 384, ob, db);
    const glm::dvec3 mappedOrigin = test::applyRigid(fromToTo, ca + oa), mappedDir = r * da;
    expectNear(db, mappedDir, kTol, "ray direction");
    // The origin lies on the mapped ray (orthographic eyes may sit elsewhere along it).
    const glm::dvec3 off = (cb + ob) - mappedOrigin;
    expectNear(off - glm::dot(off, mappedDir) * mappedDir, glm::dvec3(0.0), kTol, "ray line");
  }
}

TEST(CameraLink, TurningColumnA30DegreesAboutZTurnsBThroughTheTransform) {
  ComparisonModel m;
  m.setGeometries(offsetFixedGeometry(), unevenMovingGeometry());
  const glm::dmat4 movingToFixed = rigid(rotation({1.0, -0.4, 0.7}, 12.5), {-5.5, 3.25, 2.0});
  m.setMovingToFixed(movingToFixed);
  RenderStateModel fixed, moving;
  fixed.update(kCamera, [](RenderParams& p) {
    p.camera.azimuthDeg = 10.0;
    p.camera.elevationDeg = 20.0;
    p.camera.zoom = 1.3;
    p.camera.panMm = {4.0, -6.0};
  });
  RenderLink link(m, fixed, moving);
  link.syncMovingToFixed();
  const glm::dvec3 before = patientView(fixed.params().camera, m.fixed()).forward;
  // The user turns column A by 30 degrees about the patient's z (the azimuth: a drag of 75
  // pixels at the view's 0.4 degrees per pixel, the camera moving against the mouse).
  CameraParams turned = fixed.params().camera;
  orbit(turned, -75.0, 0.0);
  fixed.update(kCamera, [&](RenderParams& p) { p.camera = turned; });
  const glm::dvec3 after = patientView(fixed.params().camera, m.fixed()).forward;
  // A's direction did turn 30 degrees about z: same z, the horizontal part turned by 30.
  EXPECT_NEAR(after.z, before.z, 1e-12);
  EXPECT_NEAR(glm::degrees(std::atan2(after.y, after.x) - std::atan2(before.y, before.x)), 30.0,
              1e-9);
  // B's view direction is A's mapped into the prior's coordinates, and its eye A's eye.
  const glm::dmat4 fixedToMoving = glm::inverse(movingToFixed);
  const PatientView a = patientView(fixed.params().camera, m.fixed());
  const PatientView b = patientView(moving.params().camera, m.moving());
  expectNear(b.forward, glm::dmat3(fixedToMoving) * a.forward, kTol, "view direction");
  expectNear(b.eyeMm, test::applyRigid(fixedToMoving, a.eyeMm), kTol, "eye");
  EXPECT_EQ(moving.params().camera.zoom, 1.3);  // perspective: the same angle of view
  // The same rays pixel by pixel, where the horizon maps onto the horizon (the transform's
  // rotation here tilts it: compare directions only then); a rotation about z keeps it.
  const glm::dmat4 aboutZ = rigid(rotation({0, 0, 1}, -17.0), {12.0, -4.0, 7.5});
  m.setMovingToFixed(aboutZ);
  expectSameRays(fixed.params().camera, m.fixed(), moving.params().camera, m.moving(),
                 glm::inverse(aboutZ));
}

TEST(CameraLink, TranslationOnlyMovesTheEyeAndCentralRayByExactlyIt) {
  const VolumeGeometry f = offsetFixedGeometry(), g = unevenMovingGeometry();
  const glm::dvec3 t(14.0, -9.5, 22.25);
  const glm::dmat4 fixedToMoving = rigid(glm::dmat3(1.0), -t);  // movingToFixed moves by +t
  CameraParams a;
  a.azimuthDeg = -35.0;
  a.elevationDeg = 15.0;
  a.zoom = 1.7;
  a.panMm = {-12.0, 8.0};
  const CameraParams b = linkedCamera(a, f, g, fixedToMoving);
  const PatientView va = patientView(a, f), vb = patientView(b, g);
  expectNear(vb.forward, va.forward, kTol, "direction");
  // The eyes differ by exactly the translation (to rounding).
  expectNear(va.eyeMm - vb.eyeMm, t, kTol, "eye");
  // The look-at point: A's minus the translation, slid along the shared central ray (the
  // engine keeps it in the plane through the prior's centre across the view).
  const glm::dvec3 off = vb.lookAtMm - (va.lookAtMm - t);
  expectNear(off - glm::dot(off, vb.forward) * vb.forward, glm::dvec3(0.0), kTol, "focal ray");
  // Where the look-at points lie at the same depth (the volumes' centres one translation
  // apart), the focal points differ by exactly the translation.
  VolumeGeometry shifted = f;
  shifted.originMm -= t;
  const PatientView vs = patientView(linkedCamera(a, f, shifted, fixedToMoving), shifted);
  expectNear(va.lookAtMm - vs.lookAtMm, t, kTol, "focal point");
  expectSameRays(a, f, b, g, fixedToMoving);
}

TEST(CameraLink, OrthographicKeepsTheMillimetresAcross) {
  const VolumeGeometry f = offsetFixedGeometry(), g = unevenMovingGeometry();
  const glm::dmat4 fixedToMoving = rigid(rotation({0, 0, 1}, 25.0), {3.0, 1.0, -2.0});
  CameraParams a;
  a.projection = Projection::Orthographic;
  a.azimuthDeg = 50.0;
  a.elevationDeg = -30.0;
  a.zoom = 2.0;
  const CameraParams b = linkedCamera(a, f, g, fixedToMoving);
  // Half the view's height in mm at either volume (ortho: the engine ties it to the radius).
  EXPECT_NEAR(patientView(b, g).engine.halfHeight, patientView(a, f).engine.halfHeight, 1e-9);
  expectSameRays(a, f, b, g, fixedToMoving);
}

TEST(CameraLink, EitherColumnLeadsWithoutEchoAndTheLookFollowsUntilUnlinked) {
  ComparisonModel m;
  m.setGeometries(offsetFixedGeometry(), unevenMovingGeometry());
  RenderStateModel fixed, moving;
  RenderLink link(m, fixed, moving);
  // No Frame of Reference in common, not aligned: the cameras are each column's own.
  fixed.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg = 40.0; });
  EXPECT_EQ(moving.params().camera.azimuthDeg, 0.0);
  const glm::dmat4 movingToFixed = rigid(rotation({0.3, 0.1, 1.0}, 8.0), {2.0, -1.0, 4.0});
  m.setMovingToFixed(movingToFixed);  // aligned: B follows A now
  expectNear(patientView(moving.params().camera, m.moving()).forward,
             glm::dmat3(glm::inverse(movingToFixed)) *
                 patientView(fixed.params().camera, m.fixed()).forward,
             kTol, "after aligning");
  // Turning B turns A (the prior leads), and A's change is not echoed back to B.
  int fixedChanges = 0, movingChanges = 0;
  const int fc = fixed.changed.connect([&](unsigned) { ++fixedChanges; });
  const int mc = moving.changed.connect([&](unsigned) { ++movingChanges; });
  CameraParams c = moving.params().camera;
  orbit(c, 30.0, -12.0);
  zoomBy(c, 1.5);
  moving.update(kCamera, [&](RenderParams& p) { p.camera = c; });
  EXPECT_EQ(movingChanges, 1);
  EXPECT_EQ(fixedChanges, 1);
  expectNear(patientView(fixed.params().camera, m.fixed()).forward,
             glm::dmat3(movingToFixed) * patientView(c, m.moving()).forward, kTol, "B leads");
  EXPECT_DOUBLE_EQ(fixed.params().camera.zoom, c.zoom);
  fixed.changed.disconnect(fc);
  moving.changed.disconnect(mc);
  // The look: a preset chosen in A is B's too; clip boxes stay each column's own.
  fixed.applyPreset("CT-Bone");
  EXPECT_EQ(moving.params().preset, "CT-Bone");
  EXPECT_EQ(moving.params().mode, fixed.params().mode);
  fixed.update(kClip, [](RenderParams& p) { p.clip.lo.x = 0.25; });
  EXPECT_EQ(moving.params().clip.lo.x, 0.0);
  link.setLookLinked(false);
  fixed.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Mip; });
  EXPECT_NE(moving.params().mode, Mode::Mip);
  link.setLookLinked(true);  // linked again: B takes A's look at once
  EXPECT_EQ(moving.params().mode, Mode::Mip);
  // Unlinked navigation: cameras part.
  m.setLinkWanted(false);
  const double bAzimuth = moving.params().camera.azimuthDeg;
  fixed.update(kCamera, [](RenderParams& p) { p.camera.azimuthDeg += 20.0; });
  EXPECT_EQ(moving.params().camera.azimuthDeg, bAzimuth);
}

}  // namespace
}  // namespace voxray
