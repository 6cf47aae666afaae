// Oblique MPR in the models (crosshair_model.h, mpr_planes.h, slice_image.h): turning the
// crosshair's axes, the planes that result, their pixels and their orientation letters.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "crosshair_model.h"
#include "slice_image.h"
#include "voxray/io/phantom.h"
#include "voxray/io/volume.h"

using namespace voxray;

namespace {

constexpr double kDeg = M_PI / 180.0;
const Orientation kViews[] = {Orientation::Axial, Orientation::Coronal, Orientation::Sagittal};

void expectNear(const glm::dvec3& got, const glm::dvec3& want, double tol) {
  EXPECT_NEAR(glm::distance(got, want), 0.0, tol)
      << "(" << got.x << ", " << got.y << ", " << got.z << ") vs (" << want.x << ", " << want.y
      << ", " << want.z << ")";
}

// stored = 3 i + 5 j + 7 k (physical the same) on anisotropic voxels: trilinear
// reconstruction reproduces a linear ramp exactly between the outer voxel centres.
Volume ramp() {
  Volume v;
  v.dims = {40, 36, 30};
  v.spacingMm = {0.8, 0.9, 1.2};
  v.originMm = {-12.0, 7.0, 30.0};
  v.voxels.resize(v.voxelCount());
  for (size_t n = 0; n < v.voxels.size(); ++n) {  // x fastest, then y, then z
    const size_t i = n % 40, j = n / 40 % 36, k = n / (40 * 36);
    v.voxels[n] = int16_t(3 * i + 5 * j + 7 * k);
  }
  return v;
}

CrosshairModel modelFor(const Volume& v) {
  CrosshairModel m;
  m.setGeometry(v.dims, v.spacingMm, v.direction);
  return m;
}

}  // namespace

TEST(Mpr, DragInAxialTurnsTheOtherNormalsAboutItsNormal) {
  const Volume v = ramp();
  CrosshairModel m = modelFor(v);
  const SliceAxes axial = sliceAxes(v.direction, Orientation::Axial);
  int notified = 0;
  m.changed.connect([&] { ++notified; });
  // Clockwise on screen by 30 degrees: the axial view's screen runs x = L, y = P, so the
  // sagittal plane's normal (L) turns towards P.
  m.rotateInView(axial, 30 * kDeg);
  EXPECT_EQ(notified, 1);
  EXPECT_TRUE(m.rotated());
  const SliceAxes sagittal = sliceAxes(v.direction, Orientation::Sagittal);
  const SliceAxes coronal = sliceAxes(v.direction, Orientation::Coronal);
  expectNear(m.frame(sagittal).normal, {std::cos(30 * kDeg), std::sin(30 * kDeg), 0}, 1e-12);
  expectNear(m.frame(coronal).normal, {-std::sin(30 * kDeg), std::cos(30 * kDeg), 0}, 1e-12);
  expectNear(m.frame(axial).normal, {0, 0, 1}, 0);  // the view turned in keeps its plane
  // On the axial screen the sagittal plane's trace, first vertical, leans by 30 degrees.
  const glm::dvec2 trace = traceOnScreen(m.frame(axial), m.frame(sagittal).normal);
  EXPECT_NEAR(std::abs(std::atan2(trace.x, trace.y)), 30 * kDeg, 1e-12);
  m.resetRotation();
  EXPECT_FALSE(m.rotated());
  expectNear(m.frame(sagittal).normal, {1, 0, 0}, 0);
}

TEST(Mpr, ThreePlanesStayOrthogonalAfterAnySequenceOfDrags) {
  Volume v = ramp();
  // A tilted acquisition: the voxel axes turned 20 degrees about an oblique axis.
  v.direction = rotationAbout(glm::normalize(glm::dvec3(1, 2, 3)), 20 * kDeg);
  CrosshairModel m = modelFor(v);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> view(0, 2);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int drag = 0; drag < 2000; ++drag) {
    const SliceAxes a = sliceAxes(v.direction, kViews[view(rng)]);
    const glm::dvec3 before = m.frame(a).normal;
    m.rotateInView(a, angle(rng));
    ASSERT_LT(glm::distance(m.frame(a).normal, before), 1e-12) << drag;
  }
  for (Orientation o : kViews) {
    const PlaneFrame f = m.frame(sliceAxes(v.direction, o));
    EXPECT_NEAR(glm::length(f.right), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(f.normal), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(f.right, f.down), 0.0, 1e-12);
    EXPECT_NEAR(std::abs(glm::dot(glm::cross(f.right, f.down), f.normal)), 1.0, 1e-12);
  }
  const glm::dvec3 a = m.frame(sliceAxes(v.direction, Orientation::Axial)).normal;
  const glm::dvec3 c = m.frame(sliceAxes(v.direction, Orientation::Coronal)).normal;
  const glm::dvec3 s = m.frame(sliceAxes(v.direction, Orientation::Sagittal)).normal;
  EXPECT_NEAR(glm::dot(a, c), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(a, s), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(c, s), 0.0, 1e-12);
}

TEST(Mpr, ClicksAndScrollsFollowTheTurnedPlaneAndResetReturnsToVoxels) {
  const Volume v = ramp();
  CrosshairModel m = modelFor(v);
  const SliceAxes axial = sliceAxes(v.direction, Orientation::Axial);
  const SliceAxes coronal = sliceAxes(v.direction, Orientation::Coronal);
  const glm::dvec3 start = m.centre();
  m.rotateInView(axial, 30 * kDeg);
  // 10 voxels (8 mm) right of the crosshair in the coronal view: along its turned right.
  const glm::dvec2 at = voxelToSlice(coronal, v.dims, start);
  m.clickInView(coronal, at.x + 10, at.y);
  const glm::dvec3 movedMm = voxelToPatientMm(v, m.centre()) - voxelToPatientMm(v, start);
  expectNear(movedMm, 8.0 * glm::dvec3(std::cos(30 * kDeg), std::sin(30 * kDeg), 0), 1e-9);
  // One slice (0.9 mm, the coronal spacing) along the coronal view's turned normal.
  const glm::dvec3 before = m.centre();
  m.scrollView(coronal, 1);
  expectNear(voxelToPatientMm(v, m.centre()) - voxelToPatientMm(v, before),
             0.9 * m.frame(coronal).normal, 1e-9);
  m.resetRotation();
  EXPECT_EQ(m.centre(), glm::round(m.centre()));
}

TEST(Mpr, AnUnturnedViewIsTodaysSlicePixelForPixel) {
  const Volume v = makeHeadPhantom(48);
  CrosshairModel m = modelFor(v);
  m.setVoxel({20, 30, 25});
  const WindowLevel wl{400, 40};
  for (Orientation o : kViews) {
    const SliceAxes a = sliceAxes(v.direction, o);
    const Image plane =
        renderPlane(v, viewPlane(v, a, m.centre(), m.rotation(o)), wl, Interp::Linear);
    const Image slice = renderSlice(v, a, m.sliceOf(a), wl, Interp::Linear);
    ASSERT_EQ(plane.width, slice.width);
    ASSERT_EQ(plane.height, slice.height);
    EXPECT_EQ(plane.rgba, slice.rgba) << toString(o);
  }
}

// The scale bar reads the view's pixel spacing (slice_view.cpp): a turned plane keeps the
// acquisition plane's size and spacing, on unit directions, so a pixel still spans the same mm.
TEST(Mpr, ATurnedPlaneKeepsThePixelSpacingTheScaleBarReads) {
  const Volume v = ramp();
  CrosshairModel m = modelFor(v);
  m.rotateInView(sliceAxes(v.direction, Orientation::Axial), 45 * kDeg);
  m.rotateInView(sliceAxes(v.direction, Orientation::Sagittal), -20 * kDeg);
  for (Orientation o : kViews) {
    const SliceAxes a = sliceAxes(v.direction, o);
    const PlaneGrid turned = viewPlane(v, a, m.centre(), m.rotation(o));
    const PlaneGrid acquisition = slicePlane(v, a, m.centre()[a.nAxis]);
    EXPECT_EQ(turned.size, acquisition.size) << toString(o);
    EXPECT_EQ(turned.spacingMm, acquisition.spacingMm) << toString(o);
    EXPECT_NEAR(glm::length(turned.uDir), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(turned.vDir), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(turned.uDir, turned.vDir), 0.0, 1e-12);
    EXPECT_FALSE(isIdentity(m.rotation(o)));  // every view turned (by one drag or both)
  }
}

TEST(Mpr, A45DegreePlaneThroughARampHasTheAnalyticValues) {
  const Volume v = ramp();
  CrosshairModel m = modelFor(v);
  const SliceAxes axial = sliceAxes(v.direction, Orientation::Axial);
  const SliceAxes sagittal = sliceAxes(v.direction, Orientation::Sagittal);
  m.rotateInView(axial, 45 * kDeg);
  const PlaneGrid g = viewPlane(v, sagittal, m.centre(), m.rotation(Orientation::Sagittal));
  expectNear(glm::cross(g.uDir, g.vDir), -glm::dvec3(std::sqrt(0.5), std::sqrt(0.5), 0), 1e-12);
  const std::vector<float> values = samplePlane(v, g, Interp::Linear, -1e9f);
  const glm::dmat3 toVoxel = glm::inverse(v.direction);
  int inside = 0;
  for (int y = 0; y < g.size.y; ++y)
    for (int x = 0; x < g.size.x; ++x) {
      const glm::dvec3 mm = g.originMm + x * g.spacingMm.x * g.uDir + y * g.spacingMm.y * g.vDir;
      const glm::dvec3 voxel = toVoxel * (mm - v.originMm) / v.spacingMm;
      if (glm::any(glm::lessThan(voxel, glm::dvec3(0.0))) ||
          glm::any(glm::greaterThan(voxel, glm::dvec3(v.dims - 1))))
        continue;
      // Values up to 3 * 39 + 5 * 35 + 7 * 29 = 495 in float: 1e-3 is rounding, not geometry.
      ASSERT_NEAR(values[size_t(y) * size_t(g.size.x) + size_t(x)],
                  3 * voxel.x + 5 * voxel.y + 7 * voxel.z, 1e-3)
          << x << "," << y;
      ++inside;
    }
  EXPECT_GT(inside, 500);
}

TEST(Mpr, OrientationLettersOnA45DegreePlaneAreMixed) {
  const Volume v = ramp();
  CrosshairModel m = modelFor(v);
  const SliceAxes axial = sliceAxes(v.direction, Orientation::Axial);
  const SliceAxes sagittal = sliceAxes(v.direction, Orientation::Sagittal);
  const SliceAxes coronal = sliceAxes(v.direction, Orientation::Coronal);
  EXPECT_EQ(frameLabels(m.frame(sagittal)), sagittal.labels);  // unturned: as before
  m.rotateInView(axial, 45 * kDeg);
  // Sagittal: right was P, now halfway between P and R; coronal: right was L, now L and P.
  EXPECT_EQ(frameLabels(m.frame(sagittal)), (std::array<std::string, 4>{"LA", "RP", "S", "I"}));
  EXPECT_EQ(frameLabels(m.frame(coronal)), (std::array<std::string, 4>{"RA", "LP", "S", "I"}));
  EXPECT_EQ(frameLabels(m.frame(axial)), axial.labels);
  EXPECT_EQ(patientLetters({0.9, 0.15, -0.4}), "LI");  // 0.15 is below the 0.2 threshold
}

TEST(Mpr, PlaneOutlinesAndNormalsForTheCommandLine) {
  const Volume v = ramp();
  // An axial plane through the centre cuts the box in its full x-y rectangle.
  const glm::dvec3 centre(20, 10, 7);
  const auto quad = planeInBox(v, centre, {0, 0, 1});
  ASSERT_EQ(quad.size(), 4u);
  for (const glm::dvec3& p : quad) {
    EXPECT_NEAR(p.z, 7.0, 1e-9);
    EXPECT_NEAR(std::abs(p.x - 19.5), 20.0, 1e-9);
    EXPECT_NEAR(std::abs(p.y - 17.5), 18.0, 1e-9);
  }
  EXPECT_TRUE(planeInBox(v, {20, 10, 100}, {0, 0, 1}).empty());  // above the box
  // A normal between axial and coronal picks the first nearest view and turns it onto it.
  const glm::dvec3 n = glm::normalize(glm::dvec3(0, 1, 1));
  const ObliqueView ov = viewForNormal(v.direction, n);
  EXPECT_EQ(ov.orientation, Orientation::Axial);
  expectNear(ov.rotation * glm::dvec3(0, 0, 1), n, 1e-12);
  // The opposite normal is the same plane, seen from the view's usual side.
  EXPECT_EQ(viewForNormal(v.direction, -n).orientation, Orientation::Axial);
  expectNear(viewForNormal(v.direction, -n).rotation * glm::dvec3(0, 0, 1), n, 1e-12);
}
