// Fused dvr (issue 36): Raycaster::setOverlay, a second volume raycast in the same pass.
// The scenes: labels_test's ball (1000 HU, radius 13 voxels, anisotropic 1 x 1.1 x 1.6 mm)
// under a faint white table, and an overlay "lesion": a sphere of kRadiusMm (1000 in, 0 out)
// around a patient point off the ball's centre, on a grid of its own (30 x 30 x 24 voxels of
// 1.5 x 0.8 x 2.0 mm, rotated about two axes and shifted), so that only patient space can
// put it where it lies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ball_scene.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/camera.h"
#include "voxray/engine/overlay.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

using test::expectCloseToReference;

constexpr double kRadiusMm = 7.0;
// Where a ray's overlay opacity changes: the table's step (500 ... 600 of 0 ... 1000) lies
// within one overlay voxel of the sphere's surface, whose diagonal is |(1.5, 0.8, 2)| = 2.6 mm.
constexpr double kMarginMm = 2.6;

glm::dvec3 patientOf(const Volume& v, const glm::dvec3& voxel) {
  return v.originMm + v.direction * (voxel * v.spacingMm);
}

// The lesion's centre: 5, -4, 3 mm from the ball's centre (LPS).
glm::dvec3 lesionCentre() {
  const Volume& v = test::anisotropicBall();
  return patientOf(v, (glm::dvec3(v.dims) - 1.0) * 0.5) + glm::dvec3(5.0, -4.0, 3.0);
}

glm::dmat3 rotation(double zDeg, double xDeg) {
  const double a = glm::radians(zDeg), b = glm::radians(xDeg);
  const glm::dmat3 rz(std::cos(a), std::sin(a), 0.0, -std::sin(a), std::cos(a), 0.0, 0.0, 0.0, 1.0);
  const glm::dmat3 rx(1.0, 0.0, 0.0, 0.0, std::cos(b), std::sin(b), 0.0, -std::sin(b), std::cos(b));
  return rz * rx;
}

// The lesion on its own grid: its centre at overlay voxel (12, 18, 9).
Volume lesion() {
  Volume o;
  o.dims = {30, 30, 24};
  o.spacingMm = {1.5, 0.8, 2.0};
  o.direction = rotation(30.0, 20.0);
  o.originMm = lesionCentre() - o.direction * (glm::dvec3(12.0, 18.0, 9.0) * o.spacingMm);
  o.unit = "Bq/ml";
  o.modality = "PT";
  o.voxels.assign(o.voxelCount(), 0);
  for (int z = 0; z < o.dims.z; ++z)
    for (int y = 0; y < o.dims.y; ++y)
      for (int x = 0; x < o.dims.x; ++x)
        if (glm::length(patientOf(o, glm::dvec3(x, y, z)) - lesionCentre()) <= kRadiusMm)
          o.voxels[o.index(x, y, z)] = 1000;
  return o;
}

// Red, transparent up to 500, OPACITY per reference step from 600.
TransferFunction redTable(double opacity) {
  return {{{0.0, {1.0, 0.0, 0.0, 0.0}},
           {500.0, {1.0, 0.0, 0.0, 0.0}},
           {600.0, {1.0, 0.0, 0.0, opacity}}}};
}

Image renderWith(const Volume& v, const RenderParams& p, const Volume* overlay,
                 const TransferFunction& tf, bool packets, bool ess = true,
                 VolumeStorage storage = VolumeStorage::Buffer) {
  Raycaster rc(test::pocl(), v, storage);
  RaycasterOptions o;
  o.packets = packets;
  o.emptySpaceSkipping = ess;
  rc.setOptions(o);
  if (overlay) rc.setOverlay(*overlay, tf);
  Image img;
  rc.render(p, img);
  return img;
}

// Each pixel's ray's distance (mm) from the lesion's centre, in patient space.
std::vector<double> lesionDistances(const Volume& v, const RenderParams& p) {
  const ViewGeometry g = makeViewGeometry(v, p);
  std::vector<double> out;
  test::forEachPixelRay(g, p, [&](const glm::dvec3& o, const glm::dvec3& d) {
    const glm::dvec3 a = patientOf(v, g.toVoxel(o)), b = patientOf(v, g.toVoxel(o + d));
    const glm::dvec3 dir = glm::normalize(b - a);
    out.push_back(glm::length(glm::cross(lesionCentre() - a, dir)));
  });
  return out;
}

}  // namespace

TEST(Overlay, FramesWithoutAnOverlayRenderAsBefore) {
  const Volume& v = test::anisotropicBall();
  const Volume o = lesion();
  const RenderParams p = test::faintTableParams();
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    const Image plain = renderWith(v, p, nullptr, {}, packets);
    Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
    RaycasterOptions opts;
    opts.packets = packets;
    rc.setOptions(opts);
    EXPECT_NE(rc.variantOptions(p).find("OVERLAY=0"), std::string::npos);
    EXPECT_FALSE(rc.hasOverlay());
    rc.setOverlay(o, redTable(0.5));
    EXPECT_TRUE(rc.hasOverlay());
    EXPECT_NE(rc.variantOptions(p).find("OVERLAY=1"), std::string::npos);
    RenderParams adaptive = p;  // the levels read the base's table alone
    adaptive.adaptiveError = 0.01;
    EXPECT_NE(rc.variantOptions(adaptive).find("ADAPTIVE=0"), std::string::npos);
    EXPECT_NE(rc.render(p).rgba, plain.rgba);
    rc.clearOverlay();
    EXPECT_EQ(rc.render(p).rgba, plain.rgba);
    // mip takes it too (fused mip); iso does not: the same kernel and pixels as without one.
    RenderParams mip = p;
    mip.mode = Mode::Mip;
    const Image plainMip = rc.render(mip);
    RenderParams iso = p;
    iso.mode = Mode::Iso;
    const Image plainIso = rc.render(iso);
    rc.setOverlay(o, redTable(0.5));
    EXPECT_NE(rc.variantOptions(mip).find("OVERLAY=1"), std::string::npos);
    EXPECT_NE(rc.render(mip).rgba, plainMip.rgba);
    EXPECT_NE(rc.variantOptions(iso).find("OVERLAY=0"), std::string::npos);
    EXPECT_EQ(rc.render(iso).rgba, plainIso.rgba);
  }
}

// Fused mip (overlay.cl's overlay_mip): where a ray passes through the lesion its largest
// value (1000) is above the window (400 ... 600, rainbow: red there), so the pixel is the
// plain mip's grey and red half and half (opacity 0.5), as the slice views fuse; where it
// passes the lesion by more than an overlay voxel the largest value is 0, below the window:
// the plain mip's pixel exactly.
TEST(Overlay, MipShowsTheOverlaysMaximumOverTheGrey) {
  const Volume& v = test::anisotropicBall();
  const Volume o = lesion();
  RenderParams p = test::faintTableParams(false);
  p.mode = Mode::Mip;
  const TransferFunction tf = overlayWindowTable(400.0, 600.0, "rainbow", 0.5);
  const std::vector<double> dist = lesionDistances(v, p);
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    const Image plain = renderWith(v, p, nullptr, {}, packets);
    const Image fused = renderWith(v, p, &o, tf, packets);
    int in = 0, out = 0;
    for (size_t i = 0; i < dist.size(); ++i) {
      const int grey = plain.rgba[4 * i];
      ASSERT_EQ(plain.rgba[4 * i + 1], grey);  // mip is grey
      if (dist[i] < kRadiusMm - kMarginMm) {
        // Half of 255 red over half the grey; packets blend the grey as stored (8 bits), one
        // ray per work-item before storing it: within one level either way.
        EXPECT_NEAR(fused.rgba[4 * i], 0.5 * grey + 127.5, 1.0) << "pixel " << i;
        EXPECT_NEAR(fused.rgba[4 * i + 1], 0.5 * grey, 1.0) << "pixel " << i;
        EXPECT_NEAR(fused.rgba[4 * i + 2], 0.5 * grey, 1.0) << "pixel " << i;
        ++in;
      } else if (dist[i] > kRadiusMm + kMarginMm) {
        for (int c = 0; c < 4; ++c)
          EXPECT_EQ(fused.rgba[4 * i + c], plain.rgba[4 * i + c]) << "pixel " << i;
        ++out;
      }
    }
    EXPECT_GT(in, 40);  // the disc is about 12 pixels across at this zoom
    EXPECT_GT(out, 2000);
    expectCloseToReference(fused, renderReference(v, p, o, tf),
                           packets ? "fused mip, packets" : "fused mip, per ray");
  }
  // A band table (green from 450 to 800 only) is not transparent only below its first visible
  // value, so no cell is left out: through the lesion the largest value (1000) shows nothing
  // and the plain pixel stays; the rim, where the largest value falls in the band, is green.
  const TransferFunction band{{{0.0, {0.0, 1.0, 0.0, 0.0}},
                               {400.0, {0.0, 1.0, 0.0, 0.0}},
                               {450.0, {0.0, 1.0, 0.0, 1.0}},
                               {800.0, {0.0, 1.0, 0.0, 1.0}},
                               {850.0, {0.0, 1.0, 0.0, 0.0}},
                               {1000.0, {0.0, 1.0, 0.0, 0.0}}}};
  const Image ref = renderReference(v, p, o, band);
  for (bool packets : {true, false}) {
    const Image plain = renderWith(v, p, nullptr, {}, packets);
    const Image fused = renderWith(v, p, &o, band, packets);
    int centre = 0, green = 0;
    for (size_t i = 0; i < dist.size(); ++i) {
      if (dist[i] < kRadiusMm - kMarginMm) {
        EXPECT_EQ(fused.rgba[4 * i + 1], plain.rgba[4 * i + 1]) << "pixel " << i;
        ++centre;
      }
      green += fused.rgba[4 * i + 1] > fused.rgba[4 * i] + 20;
    }
    EXPECT_GT(centre, 40);
    EXPECT_GT(green, 10);  // the rim
    expectCloseToReference(fused, ref, packets ? "band mip, packets" : "band mip, per ray");
  }
}

TEST(Overlay, KernelsMatchTheReference) {
  const Volume& v = test::anisotropicBall();
  const Volume o = lesion();
  const TransferFunction tf = redTable(0.1);
  for (bool shading : {true, false}) {
    const RenderParams p = test::faintTableParams(shading);
    const Image ref = renderReference(v, p, o, tf);
    for (bool packets : {true, false})
      expectCloseToReference(
          renderWith(v, p, &o, tf, packets), ref,
          std::string(shading ? "shaded" : "unshaded") + (packets ? " packets" : " per ray"));
    // The volume as an image (GPUs), the overlay still a buffer beside it.
    if (test::pocl().device().imageSupport)
      expectCloseToReference(renderWith(v, p, &o, tf, false, true, VolumeStorage::Image3d), ref,
                             shading ? "shaded image3d" : "unshaded image3d");
  }
}

TEST(Overlay, TheLesionShowsWhereItLiesInPatientSpace) {
  const Volume& v = test::anisotropicBall();
  const Volume o = lesion();
  RenderParams p = test::faintTableParams(false);
  // The base wholly transparent: every macro cell of it empty, so only the overlay's cells
  // keep the rays sampling (skipping must not leap them).
  p.transferFunction = {{-1000.0, {1.0, 1.0, 1.0, 0.0}}, {3000.0, {1.0, 1.0, 1.0, 0.0}}};
  const std::vector<double> dist = lesionDistances(v, p);
  const TransferFunction tf = redTable(0.6);
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    const Image img = renderWith(v, p, &o, tf, packets);
    int in = 0, out = 0;
    for (size_t i = 0; i < dist.size(); ++i) {
      const int r = img.rgba[4 * i], g = img.rgba[4 * i + 1], b = img.rgba[4 * i + 2];
      EXPECT_EQ(g, 0) << "pixel " << i;  // red only: the base shows nothing
      EXPECT_EQ(b, 0) << "pixel " << i;
      if (dist[i] < kRadiusMm - kMarginMm) {
        // A chord of at least 2 sqrt(7^2 - 4.4^2) = 10.9 mm at opacity 0.6 per mm: opaque.
        EXPECT_GE(r, 250) << "pixel " << i << " at " << dist[i] << " mm";
        ++in;
      } else if (dist[i] > kRadiusMm + kMarginMm) {
        EXPECT_EQ(r, 0) << "pixel " << i << " at " << dist[i] << " mm";
        ++out;
      }
    }
    EXPECT_GT(in, 40);  // the disc is about 12 pixels across at this zoom
    EXPECT_GT(out, 2000);
    // Skipping stays exact: the same pixels without it.
    EXPECT_EQ(test::maxDiff(img, renderWith(v, p, &o, tf, packets, false)), 0);
  }
  // The reference places it the same way.
  const Image ref = renderReference(v, p, o, tf);
  expectCloseToReference(renderWith(v, p, &o, tf, true), ref, "lesion");
}

TEST(Overlay, SkippingStaysExactBesideAVisibleBase) {
  const Volume& v = test::anisotropicBall();
  const Volume o = lesion();
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    const RenderParams p = test::faintTableParams();
    EXPECT_EQ(test::maxDiff(renderWith(v, p, &o, redTable(0.2), packets, true),
                            renderWith(v, p, &o, redTable(0.2), packets, false)),
              0);
  }
}

TEST(Overlay, AnOverlayThatIsTheVolumeDoublesItsOpacity) {
  // The volume fused with itself under its own table: per reference step 1 - (1 - a)^2, the
  // colour unchanged (unshaded: both halves of the mix are the table's colour). That is the
  // volume alone with its opacities holding over half the length (opacityUnitMm 0.5 of the
  // smallest spacing, 1 mm): (1 - a)^(2 seg / 1 mm).
  const Volume& v = test::anisotropicBall();
  const RenderParams p = test::faintTableParams(false);
  RenderParams half = p;
  half.opacityUnitMm = 0.5;
  const TransferFunction tf{p.transferFunction};
  // The double reference: equal to rounding (one level, quantisation of equal values).
  EXPECT_LE(test::maxDiff(renderReference(v, p, v, tf), renderReference(v, half)), 1);
  for (bool packets : {true, false})
    expectCloseToReference(renderWith(v, p, &v, tf, packets), renderReference(v, half),
                           packets ? "self packets" : "self per ray");
  // And it is denser than the volume alone.
  const Image alone = renderReference(v, p), twice = renderReference(v, p, v, tf);
  long sumAlone = 0, sumTwice = 0;
  for (size_t i = 0; i < alone.rgba.size(); i += 4)
    sumAlone += alone.rgba[i], sumTwice += twice.rgba[i];
  EXPECT_GT(sumTwice, sumAlone + sumAlone / 4);
}

TEST(Overlay, WithoutASharedFrameOfReferenceItRendersAndWarns) {
  Volume v = test::anisotropicBall();
  Volume o = lesion();
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  v.study.frameOfReferenceUid = "1.2.3";
  o.study.frameOfReferenceUid = "1.2.3";
  EXPECT_TRUE(overlayWarnings(v, o).empty());
  o.study.frameOfReferenceUid = "1.2.4";
  const std::vector<std::string> w = overlayWarnings(v, o);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("name different Frames of Reference"), std::string::npos) << w[0];
  o.study.frameOfReferenceUid.clear();
  EXPECT_NE(overlayWarnings(v, o)[0].find("do not both name a Frame of Reference"),
            std::string::npos);
  // The raycaster's volume (ballVolume) names none: it warns and renders the lesion.
  const std::vector<std::string> fromRaycaster = rc.setOverlay(o, redTable(0.6));
  ASSERT_EQ(fromRaycaster.size(), 1u);
  EXPECT_NE(rc.render(test::faintTableParams()).rgba,
            renderWith(test::anisotropicBall(), test::faintTableParams(), nullptr, {}, true).rgba);
}

TEST(Overlay, AnOverlayTooBigForTheDeviceIsRefusedSayingWhy) {
  EXPECT_NO_THROW(checkOverlayFits(1000, 1000));
  try {
    checkOverlayFits(1001, 1000);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Device);
    EXPECT_NE(std::string(e.what()).find("needs 1001 bytes"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("allows 1000"), std::string::npos) << e.what();
  }
}

TEST(Overlay, AWindowAndColourMapMakeATable) {
  const TransferFunction tf = overlayWindowTable(2.0, 10.0, "hot-iron", 0.5);
  EXPECT_DOUBLE_EQ(tf.evaluate(2.0).a, 0.0);
  EXPECT_DOUBLE_EQ(tf.evaluate(6.0).a, 0.25);
  EXPECT_DOUBLE_EQ(tf.evaluate(10.0).a, 0.5);
  EXPECT_DOUBLE_EQ(tf.evaluate(50.0).a, 0.5);
  EXPECT_EQ(glm::dvec3(tf.evaluate(10.0)), glm::dvec3(1.0));  // hot-iron ends white
  EXPECT_EQ(glm::dvec3(overlayWindowTable(0, 1, "grey", 1).evaluate(0.5)), glm::dvec3(0.5));
  EXPECT_THROW(overlayWindowTable(0.0, 1.0, "jet", 1.0), Error);
  EXPECT_THROW(overlayWindowTable(1.0, 1.0, "grey", 1.0), Error);
  EXPECT_DOUBLE_EQ(scaledOpacity(tf, 0.5).evaluate(10.0).a, 0.25);
}

}  // namespace voxray
