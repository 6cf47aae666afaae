// The OpenCL kernels (on PoCL) against the double-precision reference renderer, pixel by
// pixel, for every mode x gradient x interpolation.
//
// Tolerance: the kernel computes in float with -cl-fast-relaxed-math, the reference in
// double. Where a sample lies within float rounding of an iso threshold, the two can
// take a different first hit (a whole step apart), so a handful of silhouette pixels may
// differ a lot; everywhere else colours agree to about one 8-bit level. We therefore
// require: mean absolute difference <= 0.5 levels, at most 0.5 % of pixels more than
// 3 levels apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "ball_scene.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/kernel_variant.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/io/synthetic.h"
#include "voxray/lab/accuracy.h"

namespace voxray {

namespace {

RenderParams baseParams(Mode mode) {
  RenderParams p = test::ballView(mode);
  p.isoLo = 0.0;
  if (mode == Mode::Dvr) {
    p.preset = "CT-Bone";
    p.stepMm = 0.5;
  }
  return p;
}

}  // namespace

// Every kernel variant that mode x gradient x interpolation compile to, once each: frames
// whose switches agree (mip with any gradient, say) run the same program.
std::vector<RenderParams> distinctVariants() {
  std::vector<RenderParams> out;
  std::set<std::string> seen;
  for (Mode mode : {Mode::Iso, Mode::Dvr, Mode::Mip})
    for (Gradient gradient : {Gradient::Central, Gradient::Sobel, Gradient::ZuckerHummel})
      for (Interp interp : {Interp::Nearest, Interp::Linear}) {
        RenderParams p = baseParams(mode);
        p.gradient = gradient;
        p.interp = interp;
        if (seen.insert(kernelVariantName(p)).second) out.push_back(p);
      }
  return out;
}

class KernelVsReference : public ::testing::TestWithParam<RenderParams> {};

TEST_P(KernelVsReference, AgreesPixelByPixel) {
  const RenderParams& p = GetParam();
  Raycaster rc(test::pocl(), test::anisotropicBall(), VolumeStorage::Buffer);
  Image gpu = rc.render(p);
  Image ref = renderReference(test::anisotropicBall(), p);
  test::expectCloseToReference(gpu, ref, rc.variantOptions(p));
  // The image is not trivially empty: the ball covers a good part of the frame.
  size_t lit = 0;
  for (size_t i = 0; i < ref.rgba.size(); i += 4) lit += ref.rgba[i] > 10;
  EXPECT_GT(lit, size_t(p.width * p.height) / 8);
}

TEST(KernelVariants, ModesGradientsAndInterpolationsMakeFourteenPrograms) {
  // iso and dvr: 3 gradients x 2 interpolations each; mip takes no gradient: 2.
  EXPECT_EQ(distinctVariants().size(), 14u);
}

INSTANTIATE_TEST_SUITE_P(AllVariants, KernelVsReference, ::testing::ValuesIn(distinctVariants()),
                         [](const auto& info) { return kernelVariantName(info.param); });

TEST(KernelVsReferenceExtras, OrthographicClipBoxAndFixedLight) {
  RenderParams p = baseParams(Mode::Iso);
  p.camera.projection = Projection::Orthographic;
  p.clip.lo = {0.0, 0.3, 0.0};
  p.clip.hi = {0.6, 1.0, 1.0};
  p.light.followCamera = false;
  p.light.position = {-200.0, -100.0, 50.0};
  Raycaster rc(test::pocl(), test::anisotropicBall(), VolumeStorage::Buffer);
  test::expectCloseToReference(rc.render(p), renderReference(test::anisotropicBall(), p),
                               rc.variantOptions(p));
}

TEST(KernelVsReferenceExtras, ImageStorageMatchesTheReferenceToo) {
  if (!test::pocl().device().imageSupport) GTEST_SKIP() << "device has no image support";
  for (Mode mode : {Mode::Iso, Mode::Dvr}) {
    RenderParams p = baseParams(mode);
    Raycaster rc(test::pocl(), test::anisotropicBall(), VolumeStorage::Image3d);
    test::expectCloseToReference(rc.render(p), renderReference(test::anisotropicBall(), p),
                                 rc.variantOptions(p));
  }
}

}  // namespace voxray

namespace voxray {

TEST(KernelVsReferenceExtras, KernelHitPointsMatchTheReferences) {
  // The HIT_OUTPUT variant's hit points against the reference renderer's, on the sphere
  // distance field (64^3, step 0.5, 8 bisections): the same crossing to float precision,
  // and the same error against the analytic surface; from the CPU packets and from one ray
  // per work-item.
  SyntheticSpec spec{SyntheticShape::Sphere, 64};
  Volume v = makeSyntheticVolume(spec);
  RenderParams p;
  p.width = 64;
  p.height = 64;
  p.mode = Mode::Iso;
  p.isoLo = 0.0;
  p.camera.azimuthDeg = 30.0;
  p.camera.elevationDeg = 25.0;
  p.stepMm = 0.5;
  p.refine = 8;
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  std::vector<glm::vec4> raw;
  FrameStats stats;
  Image img;
  ReferenceHits ref;
  renderReferenceFloat(v, p, &ref);
  for (bool packets : {true, false}) {
    SCOPED_TRACE(packets ? "packets" : "one ray per work-item");
    RaycasterOptions o;
    o.packets = packets;
    rc.setOptions(o);
    img = rc.renderWithHits(p, raw, &stats);
    EXPECT_NE(stats.variant.find("HIT_OUTPUT=1"), std::string::npos) << stats.variant;
    // The extra output changes no pixel of the kernel it extends.
    EXPECT_EQ(rc.render(p).rgba, img.rgba);
    ASSERT_EQ(raw.size(), size_t(64 * 64));
    ReferenceHits kernel = kernelHits(raw, p.width, p.height);
    int both = 0, kindDiffers = 0;
    double worst = 0.0;
    for (size_t i = 0; i < raw.size(); ++i) {
      kindDiffers += kernel.kind[i] != ref.kind[i];
      if (kernel.kind[i] != HitKind::Surface || ref.kind[i] != HitKind::Surface) continue;
      ++both;
      worst = std::max(worst, glm::distance(kernel.voxel[i], ref.voxel[i]));
    }
    EXPECT_GT(both, 300);       // 432 of 64 x 64 see the sphere
    EXPECT_LE(kindDiffers, 2);  // float vs double may flip a grazing ray
    // A last bisection decided the other way moves the hit by step / 2^8 = 0.002 voxel.
    EXPECT_LT(worst, 0.0025);
    double kernelErr = surfaceError(kernel, AnalyticField{spec}).positionVoxels.mean;
    double refErr = surfaceError(ref, AnalyticField{spec}).positionVoxels.mean;
    std::string kind = packets ? "packets_" : "";
    RecordProperty(kind + "kernel_surface_mean", std::to_string(kernelErr));
    RecordProperty("reference_surface_mean", std::to_string(refErr));
    RecordProperty(kind + "worst_hit_distance", std::to_string(worst));
    EXPECT_NEAR(kernelErr, refErr, 0.05 * refErr);
    EXPECT_LT(kernelErr, 0.02);
  }

  // mip leaves every pixel without a hit (dvr picks: dvr_pick_test.cpp).
  p.mode = Mode::Mip;
  rc.renderWithHits(p, raw);
  EXPECT_TRUE(std::all_of(raw.begin(), raw.end(), [](const glm::vec4& h) { return h.w == -1.0f; }));
  // And a plain frame afterwards is the plain variant again.
  p.mode = Mode::Iso;
  rc.render(p, img, &stats);
  EXPECT_NE(stats.variant.find("HIT_OUTPUT=0"), std::string::npos) << stats.variant;
}

}  // namespace voxray
