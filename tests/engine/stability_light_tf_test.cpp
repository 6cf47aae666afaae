// Stability of shading and transfer functions: lights inside the volume, at the hit point
// and at 1e30 mm; an opacity of exactly 1 at the first sample; coincident control points;
// jittered ray starts (kernel and reference must place samples identically).
#include <gtest/gtest.h>

#include <cmath>

#include "reference_sampling.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/engine/transfer_function.h"

namespace voxray {

namespace {

RenderParams fixedLight(Mode m, glm::dvec3 light) {
  RenderParams p = test::tinyParams(m);
  p.light.followCamera = false;
  p.light.position = light;
  return p;
}

}  // namespace

TEST(StabilityLight, InsideTheVolumeAtTheHitPointAndFarAway) {
  // Orthographic from anterior: the centre ray meets the ball (radius 5 voxels at the
  // centre, blended over a voxel) near world (0, -5, 0); the light sits right there.
  for (Mode m : {Mode::Iso, Mode::Dvr})
    for (glm::dvec3 light : {glm::dvec3(0.0), glm::dvec3(0.0, -5.0, 0.0), glm::dvec3(1e30),
                             glm::dvec3(-1e30, 1e30, 0.0)}) {
      RenderParams p = fixedLight(m, light);
      p.camera.projection = Projection::Orthographic;
      test::expectStable(test::ball16(), p, "light at " + std::to_string(light.x));
    }
}

TEST(StabilityTransferFunction, OpacityExactlyOneInTheFirstSample) {
  // Iso-Bone's table is opaque (alpha exactly 1) above 400 HU: in a constant 1000 HU
  // volume the first dvr sample ends every ray, with and without opacity correction, whose
  // 1 - (1 - a)^(seg / ref) must not become 0^0 or NaN for any segment length.
  Volume v = test::constant({8, 8, 8}, 1000);
  for (bool correction : {true, false})
    for (double step : {1e-3, 0.5, 7.0}) {
      RenderParams p = test::tinyParams(Mode::Dvr);
      p.preset = "Iso-Bone";
      p.opacityCorrection = correction;
      p.stepMm = step;
      test::expectStable(v, p, "alpha 1, step " + std::to_string(step));
      FloatImage f = renderReferenceFloat(v, p);
      // Lit bone colour, not background: the first sample was fully opaque.
      EXPECT_GT(f.rgb[(12 * 32 + 16) * 3], 0.1f);
    }
}

namespace {
// Three points at 100 HU: a hard step from transparent black to opaque red; the middle
// point (white, half opaque) has zero width and must never show.
const std::vector<ControlPoint> kStep = {{-1000.0, {0, 0, 0, 0}},
                                         {100.0, {0, 0, 0, 0}},
                                         {100.0, {1, 1, 1, 0.5}},
                                         {100.0, {1, 0, 0, 1}},
                                         {1000.0, {1, 0, 0, 1}}};
}  // namespace

TEST(StabilityTransferFunction, CoincidentControlPointsMakeAStepWithoutNaN) {
  TransferFunction tf{kStep};
  EXPECT_EQ(tf.evaluate(99.999), glm::dvec4(0.0, 0.0, 0.0, 0.0));
  EXPECT_EQ(tf.evaluate(100.0), glm::dvec4(1, 0, 0, 1));
  Volume v = test::rampX({201, 1, 1}, -1000.0, 10.0);  // -1000 ... 1000 HU in 10 HU steps
  Lut lut = bakeLut(tf, v);
  for (const glm::vec4& e : lut.rgba)
    for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(e[c]));
  EXPECT_EQ(lut.lookup(v.toStored(90.0)).a, 0.0);
  EXPECT_EQ(lut.lookup(v.toStored(110.0)).a, 1.0);
}

TEST(StabilityTransferFunction, CoincidentControlPointsRenderThroughBothRenderers) {
  // The table reaches the renderers as RenderParams::transferFunction (--tf on the CLI).
  RenderParams text;
  fromText(text, "tf=1000:1:0:0:1,100:1:0:0:1,100:1:1:1:0.5,100:0:0:0:0,-1000:0:0:0:0\n");
  ASSERT_EQ(text.transferFunction.size(), 5u);
  EXPECT_EQ(text.transferFunction[1].rgba, glm::dvec4(1, 0, 0, 1)) << "stable sort by HU";
  for (Mode m : {Mode::Dvr, Mode::Iso})
    for (bool shading : {true, false}) {
      RenderParams p = test::tinyParams(m);
      p.transferFunction = kStep;
      p.shading = shading;
      if (m == Mode::Iso) p.isoLo = 100.0;  // the surface sits on the step
      test::expectStable(test::ball16(), p,
                         std::string("step at 100 HU, shading ") + (shading ? "on" : "off"));
    }
  // Unshaded dvr: every ray through the ball meets the step and stops on opaque red; the
  // zero-width white point adds nothing to green or blue.
  RenderParams p = test::tinyParams(Mode::Dvr);
  p.transferFunction = kStep;
  p.shading = false;
  Raycaster rc(test::pocl(), test::ball16(), VolumeStorage::Buffer);
  for (const Image& img : {rc.render(p), renderReference(test::ball16(), p)}) {
    const uint8_t* c = img.pixel(16, 12);
    EXPECT_GE(c[0], 250);
    EXPECT_EQ(c[1], 0);
    EXPECT_EQ(c[2], 0);
  }
}

TEST(StabilityJitter, ReferenceHashIsTheKernelsHash) {
  // Values of the hash in raycast.cl's comment, computed by hand once.
  EXPECT_EQ(jitterFraction(0, 0), 0.0f);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      float j = jitterFraction(x, y);
      EXPECT_GE(j, 0.0f);
      EXPECT_LT(j, 1.0f);
    }
}

TEST(StabilityJitter, KernelAndReferencePlaceJitteredSamplesAlike) {
  Raycaster rc(test::pocl(), test::ball16(), VolumeStorage::Buffer);
  RenderParams probe = test::tinyParams(Mode::Dvr);
  probe.jitter = true;
  if (rc.variantOptions(probe).find("JITTER") == std::string::npos)
    GTEST_SKIP() << "the kernel does not implement jitter yet (" << rc.variantOptions(probe) << ")";
  for (Mode m : {Mode::Iso, Mode::Dvr, Mode::Mip})
    for (double step : {0.5, 2.0}) {
      RenderParams p = test::tinyParams(m);
      p.jitter = true;
      p.stepMm = step;
      test::expectStable(test::ball16(), p, "jitter, step " + std::to_string(step));
    }
}

}  // namespace voxray
