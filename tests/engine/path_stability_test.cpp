// Numerical stability of the path tracer (issue 15): light inside the volume and at
// infinity, opacity 0 and 1 everywhere, a one-voxel volume, spacing 0.01 x 50 mm. Kernel
// and reference: no NaN, no Inf, no negative radiance; the kernel's image twice the same.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "path_test_scenes.h"
#include "test_volumes.h"
#include "voxray/engine/path_reference.h"

namespace voxray {

namespace {

void expectFiniteNonNegative(const FloatImage& f, const std::string& what) {
  ASSERT_EQ(f.rgb.size(), size_t(f.width) * size_t(f.height) * 3) << what;
  int bad = 0;
  for (float x : f.rgb) bad += !(std::isfinite(x) && x >= 0.0f);
  EXPECT_EQ(bad, 0) << what;
}

void expectStablePaths(const Volume& v, const RenderParams& p, const std::string& what) {
  test::PathImage a = test::pathRender(v, p, 4), b = test::pathRender(v, p, 4);
  expectFiniteNonNegative(a.radiance, what + " (kernel)");
  EXPECT_EQ(a.radiance.rgb, b.radiance.rgb) << what;
  expectFiniteNonNegative(renderPathReference(v, p, 2).mean, what + " (reference)");
}

}  // namespace

TEST(PathStability, LightInsideAtTheSurfaceAndAtInfinity) {
  Volume v = test::ballVolume();
  for (glm::dvec3 light : {glm::dvec3(0.0), glm::dvec3(0.0, -5.0, 0.0), glm::dvec3(1e30),
                           glm::dvec3(-1e30, 1e30, 0.0), glm::dvec3(3e38, 0.0, 0.0)}) {
    RenderParams p = test::ballParams();
    p.light.followCamera = false;
    p.light.position = light;
    expectStablePaths(v, p, "light at " + std::to_string(light.x) + "," + std::to_string(light.y));
  }
}

TEST(PathStability, OpacityZeroAndOneEverywhere) {
  Volume v = test::slabVolume();
  // Opacity 0: no collision anywhere; every pixel is exactly the background.
  RenderParams p = test::slabParams(0.0, glm::dvec3(1.0));
  p.background = glm::dvec3(0.25, 0.5, 0.75);
  test::PathImage a = test::pathRender(v, p, 4);
  for (size_t i = 0; i < a.radiance.rgb.size(); ++i)
    ASSERT_EQ(a.radiance.rgb[i], float(p.background[int(i % 3)])) << "value " << i;
  // Opacity 1 (capped at 0.999 per mm): opaque white, lit by light and environment.
  expectStablePaths(v, test::slabParams(1.0, glm::dvec3(1.0)), "opacity 1");
  RenderParams q = test::slabParams(1.0, glm::dvec3(1.0));
  q.light.followCamera = false;
  q.light.position = glm::dvec3(0.0, 0.0, 0.0);  // inside the opaque block
  expectStablePaths(v, q, "opacity 1, light inside");
}

TEST(PathStability, OneVoxelAndExtremeSpacing) {
  Volume one = test::constant({1, 1, 1}, 0);
  expectStablePaths(one, test::slabParams(0.5, glm::dvec3(0.8)), "one voxel");
  Volume thin = test::constant({8, 8, 4}, 0);
  thin.spacingMm = glm::dvec3(0.01, 0.01, 50.0);
  for (double alpha : {0.3, 1.0}) {
    RenderParams p = test::slabParams(alpha, glm::dvec3(0.8));
    p.width = 16;
    p.height = 12;
    for (double az : {0.0, 90.0}) {
      p.camera.azimuthDeg = az;
      expectStablePaths(thin, p, "spacing 0.01 x 50, alpha " + std::to_string(alpha));
    }
  }
}

}  // namespace voxray
