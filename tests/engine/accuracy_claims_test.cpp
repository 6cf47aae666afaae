// The literature claims the accuracy sweep checks, as assertions on the analytic volumes
// (double-precision reference renderer: the kernels follow it within the tolerance of
// kernel_vs_reference_test.cpp). The numbers in comments were measured with this code.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "reference_sampling.h"
#include "voxray/engine/accuracy.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/io/synthetic.h"

namespace voxray {

namespace {

RenderParams isoParams(double stepVoxels, int refine, Gradient g = Gradient::ZuckerHummel) {
  RenderParams p;
  p.width = 96;
  p.height = 96;
  p.mode = Mode::Iso;
  p.isoLo = 0.0;  // analytic surfaces are at value 0
  p.camera.azimuthDeg = 30.0;
  p.camera.elevationDeg = 25.0;
  p.camera.zoom = 1.2;
  p.stepMm = stepVoxels;  // 1 mm voxels
  p.refine = refine;
  p.gradient = g;
  return p;
}

const Volume& ml41() {
  static Volume v = makeSyntheticVolume({SyntheticShape::MarschnerLobb, 41});
  return v;
}

}  // namespace

TEST(Synthetic, TrilinearReconstructsTheRampExactly) {
  SyntheticSpec spec{SyntheticShape::RampX, 16};
  Volume v = makeSyntheticVolume(spec);
  AnalyticField f{spec};
  std::mt19937 rng(7);
  // Inside [1, 14]: the gradient stencils then never reach the clamped edge.
  std::uniform_real_distribution<double> u(1.0, 14.0);
  for (int i = 0; i < 1000; ++i) {
    glm::dvec3 p(u(rng), u(rng), u(rng));
    EXPECT_NEAR(v.toPhysical(sampleVolume(v, Interp::Linear, p)), f.value(p), 1e-9);
    glm::dvec3 g = volumeGradient(v, Interp::Linear, Gradient::Sobel, glm::round(p));
    EXPECT_NEAR(g.x * v.slope, 100.0, 1e-9);  // 100 per voxel, exactly, away from clamping
  }
}

TEST(Synthetic, AnalyticGradientsMatchFiniteDifferences) {
  for (SyntheticShape s : {SyntheticShape::MarschnerLobb, SyntheticShape::Sphere,
                           SyntheticShape::Torus, SyntheticShape::RampX}) {
    AnalyticField f{{s, 41}};
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(2.0, 38.0);
    for (int i = 0; i < 200; ++i) {
      glm::dvec3 p(u(rng), u(rng), u(rng)), fd;
      for (int a = 0; a < 3; ++a) {
        glm::dvec3 e(0.0);
        e[a] = 1e-5;
        fd[a] = (f.value(p + e) - f.value(p - e)) / 2e-5;
      }
      EXPECT_LE(glm::length(fd - f.gradient(p)), 1e-4 * (1.0 + glm::length(fd))) << toString(s);
    }
  }
}

TEST(Synthetic, SignedDistanceSurfacesAreFoundToAFewHundredthsOfAVoxel) {
  // What is left is trilinear's error on a curved distance field (about h^2 / 8r).
  // Measured, 96x96, step 0.5, 8 bisections: sphere64 0.0086 / torus64 0.011 voxels mean;
  // normals 0.01 / 0.11 degrees.
  for (SyntheticShape s : {SyntheticShape::Sphere, SyntheticShape::Torus}) {
    SyntheticSpec spec{s, 64};
    Volume v = makeSyntheticVolume(spec);
    ReferenceHits hits;
    renderReferenceFloat(v, isoParams(0.5, 8), &hits);
    SurfaceError e = surfaceError(hits, AnalyticField{spec});
    EXPECT_GT(e.positionVoxels.count, 500) << toString(s);
    EXPECT_LT(e.positionVoxels.mean, 0.03) << toString(s);
    EXPECT_LT(e.normalDeg.mean, 0.5) << toString(s);
  }
}

TEST(LiteratureClaims, SmoothingGradientsDoNotBeatCentralDifferencesOnCleanMarschnerLobb) {
  // The literature's claim (Sobel / Zucker-Hummel normals beat central differences on
  // Marschner-Lobb) is NOT reproduced on the noise-free trilinear signal: their 3x3x3
  // smoothing attenuates the radial ripples (near Nyquist at 41^3) more than the slow z
  // term, which tilts the normal. Measured mean angular error, step 0.25, 8 bisections,
  // 96x96: 41^3 central 37.6, Sobel 45.5, Zucker-Hummel 51.1 degrees (p95 ~78 for all);
  // the sweep finds the same order at 81^3 (9.2 / 10.1 / 11.2) and 161^3 (2.5 / 2.7 / 2.9).
  // This test pins the finding so a change to the operators shows up here.
  double mean[3], p95[3];
  for (Gradient g : {Gradient::Central, Gradient::Sobel, Gradient::ZuckerHummel}) {
    ReferenceHits hits;
    renderReferenceFloat(ml41(), isoParams(0.25, 8, g), &hits);
    SurfaceError e = surfaceError(hits, AnalyticField{{SyntheticShape::MarschnerLobb, 41}});
    mean[int(g)] = e.normalDeg.mean;
    p95[int(g)] = e.normalDeg.p95;
    RecordProperty(std::string("normal_mean_deg_") + toString(g), std::to_string(mean[int(g)]));
  }
  int c = int(Gradient::Central), s = int(Gradient::Sobel), z = int(Gradient::ZuckerHummel);
  EXPECT_LT(mean[c], mean[s]);
  EXPECT_LT(mean[s], mean[z]);
  EXPECT_NEAR(p95[s], p95[c], 5.0);
  EXPECT_NEAR(p95[z], p95[c], 5.0);
}

TEST(LiteratureClaims, EachBisectionStepRoughlyHalvesTheHitPointError) {
  // Hit point against the same trilinear field marched at 1/16 voxel with 24 bisections,
  // ML 41^3, 1-voxel step, 96x96. Measured median (mean) in voxels: r0 0.416 (0.444),
  // r1 0.122 (0.127), r2 0.0623 (0.0658), r3 0.0303 (0.0347), r4 0.0163 (0.0203),
  // r5 0.00802 (0.0119), r6 0.00399 (0.0080), r7 0.00197 (0.0061), r8 0.00099 (0.0051).
  // r0 -> r1 gains 3.4x (the hit becomes the bracket's midpoint), each later step exactly
  // 2x. r0 / r6 = 104x, r0 / r5 = 52x: the seed's "5-6 steps give a 64x better hit
  // point" holds at 6 steps for the typical ray. The mean stalls near 0.005 voxel: ~3 % of
  // rays bracket a different crossing less than a voxel away (a ripple the 1-voxel march
  // stepped over); 372 of ~2400 rays found a crossing over a voxel away and are excluded.
  RenderParams fineP = isoParams(1.0 / 16, 24);
  ReferenceHits fine;
  renderReferenceFloat(ml41(), fineP, &fine);
  double err[9];
  for (int r = 0; r <= 8; ++r) {
    ReferenceHits hits;
    renderReferenceFloat(ml41(), isoParams(1.0, r), &hits);
    // Rays whose 1-voxel march found another crossing than the fine march (stepped over
    // a thin ripple) are left out: refinement cannot fix those.
    ErrorStats e = hitPointError(hits, fine, 1.0);
    ASSERT_GT(e.count, 1000);
    err[r] = e.median;
    RecordProperty("hit_error_r" + std::to_string(r), std::to_string(err[r]));
  }
  EXPECT_GT(err[0] / err[1], 3.0);
  for (int r = 1; r < 8; ++r) {
    EXPECT_GT(err[r] / err[r + 1], 1.6) << "step " << r;
    EXPECT_LT(err[r] / err[r + 1], 2.5) << "step " << r;
  }
  EXPECT_GE(err[0] / err[6], 64.0);
  EXPECT_LT(err[0] / err[5], 64.0);
}

TEST(LiteratureClaims, SurfaceErrorAgainstTheTrueSurfaceStopsAtTheReconstructionError) {
  // Bisection finds the trilinear field's crossing, not Marschner-Lobb's: past a few
  // steps the error against the analytic surface stops falling (measured mean: r0 0.47,
  // r4 0.10, r8 0.10 voxels at a 1-voxel step).
  AnalyticField truth{{SyntheticShape::MarschnerLobb, 41}};
  double err[3];
  int steps[3] = {0, 4, 8};
  for (int i = 0; i < 3; ++i) {
    ReferenceHits hits;
    renderReferenceFloat(ml41(), isoParams(1.0, steps[i]), &hits);
    err[i] = surfaceError(hits, truth).positionVoxels.mean;
  }
  EXPECT_GT(err[0], 2.0 * err[1]);
  EXPECT_NEAR(err[2], err[1], 0.2 * err[1]);
}

}  // namespace voxray
