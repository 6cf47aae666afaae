// Numerical stability of shadows and ao (issue 15's last section): the light inside the
// volume and at infinity, opacity 0 and 1 everywhere, a one-voxel volume, spacing 0.01 x
// 50 mm. Every case: the Monte Carlo reference is finite, in [0, 1] and the same twice
// for one seed; both kernel paths give the same image twice, and stay near the reference
// (a NaN in the kernel would show as a black pixel: convert_uchar_sat makes it 0).
#include <gtest/gtest.h>

#include <cmath>

#include "lighting_scenes.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/monte_carlo_reference.h"
#include "voxray/engine/raycaster.h"

namespace voxray {

namespace {

void expectLightingStable(const Volume& v, RenderParams p, const std::string& what) {
  for (Lighting l : {Lighting::Shadows, Lighting::Ao}) {
    p.lighting = l;
    SCOPED_TRACE(what + " [" + toString(l) + "]");
    MonteCarloOptions o;
    o.samples = 4;
    MonteCarloImage ref = renderMonteCarlo(v, p, o);
    for (float x : ref.mean.rgb) {
      ASSERT_TRUE(std::isfinite(x));
      ASSERT_GE(x, 0.0f);
      ASSERT_LE(x, 1.0f);
    }
    for (float e : ref.stdError) ASSERT_TRUE(std::isfinite(e));
    EXPECT_EQ(renderMonteCarlo(v, p, o).mean.rgb, ref.mean.rgb);
    for (bool packets : {true, false}) {
      Raycaster rc(test::pocl(), v);
      RaycasterOptions ro = rc.options();
      ro.packets = packets;
      rc.setOptions(ro);
      Image a = rc.render(p);
      Image b = rc.render(p);
      EXPECT_EQ(test::maxDiff(a, b), 0);
      double sum = 0.0;
      for (size_t i = 0; i < ref.mean.rgb.size(); ++i)
        sum += std::abs(a.rgba[(i / 3) * 4 + i % 3] / 255.0 - ref.mean.rgb[i]);
      // Mean absolute error 0.1 (26 levels): loose, for the grid on these extreme scenes
      // (an opaque cube's faces measured 0.067: the grid resolves the shadow offset's exit
      // through a face only to a cell); a NaN (black) or Inf (white) image would exceed it.
      EXPECT_LT(sum / double(ref.mean.rgb.size()), 0.1) << (packets ? "packets" : "one ray");
    }
  }
}

RenderParams litBallParams(glm::dvec3 light) {
  RenderParams p = test::tinyParams(Mode::Dvr);
  p.light.followCamera = false;
  p.light.position = light;
  return p;
}

}  // namespace

TEST(LightingStability, LightInsideTheVolumeAndAtInfinity) {
  Volume v = test::ball({16, 16, 16}, 5.0);
  for (glm::dvec3 light : {glm::dvec3(0.0), glm::dvec3(0.0, -5.0, 0.0), glm::dvec3(1e30),
                           glm::dvec3(-1e30, 1e30, 0.0)})
    expectLightingStable(v, litBallParams(light), "light at " + std::to_string(light.x));
}

TEST(LightingStability, OpacityZeroAndOneEverywhere) {
  Volume v = test::constant({12, 12, 12}, 300);
  for (double alpha : {0.0, 1.0}) {
    RenderParams p = test::litParams(Lighting::Shadows, test::uniformOpacity(alpha),
                                     glm::dvec3(20.0, -30.0, 40.0), 32, 24);
    expectLightingStable(v, p, "opacity " + std::to_string(alpha));
  }
}

TEST(LightingStability, OneVoxelVolume) {
  Volume v = test::constant({1, 1, 1}, 1000);
  RenderParams p = test::litParams(Lighting::Shadows, test::uniformOpacity(0.5),
                                   glm::dvec3(3.0, -2.0, 1.0), 16, 12);
  expectLightingStable(v, p, "one voxel");
}

TEST(LightingStability, ExtremeSpacing) {
  // 0.01 mm in-plane, 50 mm between slices: the grid's cells and the occlusion radius
  // (10 mm) span very different voxel counts along the axes.
  Volume v = test::ball({16, 16, 4}, 5.0, 1000.0, -1000.0, glm::dvec3(0.01, 0.01, 50.0));
  expectLightingStable(v, litBallParams(glm::dvec3(0.05, -0.05, 80.0)), "0.01 x 50 mm");
}

}  // namespace voxray
