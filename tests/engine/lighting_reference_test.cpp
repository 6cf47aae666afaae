// The Monte Carlo reference (monte_carlo_reference.h) against closed forms: the
// transmittance of a uniform medium, the ambient visibility above an opaque half-space,
// the shadow a sphere casts on a plane under a point light, and a region behind an opaque
// slab left with its ambient light only. Each estimate must agree within 4 of its own
// standard errors, plus, where the voxelised scene differs from the ideal one, a stated
// geometric allowance.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "frame_setup.h"
#include "lighting_scenes.h"
#include "voxray/engine/monte_carlo_reference.h"

namespace voxray {

namespace {

constexpr double kPi = 3.14159265358979323846;

double sigmaOf(const Volume& v, const RenderParams& p, double alpha) {
  return -std::log(1.0 - alpha) / makeFrameSetup(v, p).referenceStepMm;
}

}  // namespace

TEST(MonteCarloReference, UniformMediumTransmittanceIsExpMinusSigmaD) {
  Volume v = test::sdfVolume({32, 32, 32}, [](const glm::dvec3&) { return -0.1; });
  for (double alpha : {0.01, 0.05, 0.2}) {
    // The light 100 mm below the centre: 16 mm of the medium (the box's half depth) lie
    // between them, less the model's shadow offset; no shadow from outside the box.
    RenderParams p = test::litParams(Lighting::Shadows, test::uniformOpacity(alpha),
                                     glm::dvec3(0.0, 0.0, -100.0));
    double sigma = sigmaOf(v, p, alpha);
    MonteCarloOptions o;
    o.samples = 64;
    Estimate t = lightTransmittance(v, p, glm::dvec3(0.0), o);
    double expected = std::exp(-sigma * (16.0 - shadowOffsetMm(v)));
    // + 1e-6: the table keeps opacity in float (sigma off by a few parts in 1e8)
    EXPECT_NEAR(t.mean, expected, 4.0 * t.stdError + 1e-6) << "alpha " << alpha;
    // Occlusion radius 10 mm lies inside the medium in every direction: A = exp(-sigma R).
    Estimate a = ambientVisibility(v, p, glm::dvec3(0.0), o);
    EXPECT_NEAR(a.mean, std::exp(-sigma * kAoRadiusMm), 4.0 * a.stdError + 1e-6);
  }
}

TEST(MonteCarloReference, AmbientVisibilityAboveAnOpaqueHalfSpace) {
  // An opaque slab below z = 19.7 voxels (20 mm thick); points h mm above it, far from the
  // box's sides: A = (1 + h / R) / 2. Allowance 0.01: the plane's last ~0.2 mm of finite
  // opacity (about 0.4 % of the sphere) lets grazing directions through.
  Volume v = test::sdfVolume({40, 40, 40}, [](const glm::dvec3& q) { return q.z - 19.7; });
  RenderParams p =
      test::litParams(Lighting::Ao, test::opaqueAboveZero(), glm::dvec3(0.0, 0.0, 500.0));
  MonteCarloOptions o;
  o.samples = 4000;
  for (double h : {1.0, 4.0, 8.0}) {
    glm::dvec3 w = test::worldOf(v, glm::dvec3(19.5, 19.5, 19.7 + h));
    Estimate a = ambientVisibility(v, p, w, o);
    double expected = 0.5 * (1.0 + h / kAoRadiusMm);
    EXPECT_NEAR(a.mean, expected, 4.0 * a.stdError + 0.01) << "h " << h;
    EXPECT_GT(a.stdError, 0.0);
  }
  // Beyond the radius nothing occludes.
  Estimate far = ambientVisibility(v, p, test::worldOf(v, glm::dvec3(19.5, 19.5, 31.0)), o);
  EXPECT_NEAR(far.mean, 1.0, 1e-9);
}

TEST(MonteCarloReference, SphereAbovePlaneShadowedFraction) {
  // A plane (top at z = 8) and a sphere (radius 8, centre z = 26) on the axis of a point
  // light at z = 200: the shadow on the plane is a disc of radius r = dL tan(theta),
  // sin(theta) = a / D (D the light-centre distance, dL the light's height above the
  // points). Points drawn uniformly in a 24 mm square around the axis, just above the
  // plane: the shadowed fraction is pi r^2 / 24^2. Allowance 0.015: the reconstructed
  // sphere's radius within 0.1 voxel (the fraction grows as the radius squared).
  const glm::dvec3 centre(31.5, 31.5, 26.0);
  const double a = 8.0, plane = 8.0, lightZ = 200.0, side = 24.0;
  Volume v = test::sdfVolume({64, 64, 48}, [&](const glm::dvec3& q) {
    return std::min(q.z - plane, glm::length(q - centre) - a);
  });
  glm::dvec3 lightVoxel(centre.x, centre.y, lightZ);
  RenderParams p =
      test::litParams(Lighting::Shadows, test::opaqueAboveZero(), test::worldOf(v, lightVoxel));
  double pointZ = plane + 0.5;
  double dL = lightZ - pointZ, D = lightZ - centre.z;
  double s = a / D, r = dL * s / std::sqrt(1.0 - s * s);
  double expected = kPi * r * r / (side * side);

  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(-0.5 * side, 0.5 * side);
  MonteCarloOptions o;
  o.samples = 2;
  const int n = 1500;
  double shadowed = 0.0;
  for (int i = 0; i < n; ++i) {
    glm::dvec3 q(centre.x + uni(rng), centre.y + uni(rng), pointZ);
    double t = lightTransmittance(v, p, test::worldOf(v, q), o).mean;
    shadowed += 1.0 - t;
  }
  double f = shadowed / n, se = std::sqrt(f * (1.0 - f) / n);
  EXPECT_NEAR(f, expected, 4.0 * se + 0.015) << "r " << r;
  EXPECT_GT(f, 0.3);  // about 0.42: the scene does cast its shadow
}

TEST(MonteCarloReference, LightBehindAnOpaqueSlabLeavesTheRegionAmbient) {
  // A faint medium under an opaque slab (lighting_scenes.h). With the light
  // above the slab the medium below gets only the ambient term: the image equals the one
  // with diffuse and specular off, within 4 standard errors. With the light below, the
  // same pixels are clearly brighter (so the comparison can fail).
  test::SlabScene scene = test::slabScene();
  const Volume& v = scene.volume;
  const RenderParams &above = scene.above, &ambientOnly = scene.ambientOnly, &below = scene.below;
  MonteCarloOptions o;
  o.samples = 16;
  MonteCarloImage dark = renderMonteCarlo(v, above, o);
  MonteCarloImage ambient = renderMonteCarlo(v, ambientOnly, o);
  MonteCarloImage lit = renderMonteCarlo(v, below, o);
  // The bottom third of the image sees the medium only (z below about 16 voxels).
  int checked = 0;
  double brighter = 0.0;
  for (int y = 2 * above.height / 3; y < above.height; ++y)
    for (int x = above.width / 4; x < 3 * above.width / 4; ++x) {
      size_t i = size_t(y) * size_t(above.width) + size_t(x);
      double se = std::hypot(dark.stdError[i], ambient.stdError[i]);
      EXPECT_NEAR(dark.mean.rgb[i * 3], ambient.mean.rgb[i * 3], 4.0 * se + 1e-6);
      brighter += lit.mean.rgb[i * 3] - dark.mean.rgb[i * 3];
      ++checked;
    }
  ASSERT_GT(checked, 50);
  EXPECT_GT(brighter / checked, 0.05);
}

TEST(MonteCarloReference, ConvergesWithSamplesAndIsDeterministic) {
  Volume v = test::sdfVolume(
      {24, 24, 24}, [](const glm::dvec3& q) { return glm::length(q - glm::dvec3(11.5)) - 7.0; });
  std::vector<ControlPoint> tf = {
      {-1000.0, {1, 1, 1, 0}}, {0.0, {1, 1, 1, 0.2}}, {1000.0, {1, 1, 1, 0.6}}};
  RenderParams p = test::litParams(Lighting::Shadows, tf, glm::dvec3(40.0, -60.0, 50.0), 24, 18);
  MonteCarloOptions few, many;
  few.samples = 8;
  many.samples = 32;
  MonteCarloImage a = renderMonteCarlo(v, p, few), b = renderMonteCarlo(v, p, many);
  // The standard error falls as 1 / sqrt(samples): a quarter of the samples, twice the error.
  EXPECT_GT(a.meanStdError(), 0.0);
  EXPECT_NEAR(b.meanStdError() / a.meanStdError(), 0.5, 0.15);
  MonteCarloImage again = renderMonteCarlo(v, p, few);
  EXPECT_EQ(a.mean.rgb, again.mean.rgb);
  EXPECT_EQ(a.stdError, again.stdError);
}

}  // namespace voxray
