// The path tracer (lighting cinematic) against closed forms and its double-precision
// reference: a slab's transmittance, an opaque slab shadowing a region, determinism,
// kernel vs reference within the reference's standard error, restarts.
#include <gtest/gtest.h>

#include <cmath>

#include "path_test_scenes.h"
#include "stability_helpers.h"
#include "voxray/engine/path_reference.h"
#include "voxray/engine/path_tracer.h"
#include "voxray/engine/raycaster.h"

namespace voxray {

namespace {

using test::PathImage;

// Mean of channel 0 over the pixels [x0, x1) x [y0, y1) and its standard error from the
// per-pixel errors (independent pixels).
struct RegionMean {
  double mean = 0.0, se = 0.0;
};
RegionMean region(const FloatImage& f, const FloatImage* se, int x0, int x1, int y0, int y1) {
  RegionMean r;
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x, ++n) {
      size_t i = (size_t(y) * size_t(f.width) + size_t(x)) * 3;
      r.mean += f.rgb[i];
      if (se) r.se += double(se->rgb[i]) * se->rgb[i];
    }
  r.mean /= n;
  r.se = std::sqrt(r.se) / n;
  return r;
}

}  // namespace

TEST(PathTracer, UniformSlabTransmitsExpOfMinusSigmaD) {
  // A black (albedo 0) absorber of opacity 0.3 per 1 mm voxel, 8 mm deep, seen
  // orthographically against a white background: a pixel's mean is the transmittance
  // exp(-sigma d) = 0.7^8 = 0.05765 (sigma = -ln 0.7 per mm). The estimator is a coin with
  // that probability, so its standard error is known in closed form too.
  Volume v = test::slabVolume();
  RenderParams p = test::slabParams(0.3, glm::dvec3(0.0));
  const double expected = std::pow(0.7, 8.0);
  const int spp = 1024;
  PathImage k = test::pathRender(v, p, spp);
  PathReference ref = renderPathReference(v, p, spp);
  // The central 8 x 8 pixels see the slab through its full depth (the frame has a margin).
  for (const FloatImage* f : {&k.radiance, &ref.mean}) {
    RegionMean m = region(*f, nullptr, 12, 20, 8, 16);
    double se = std::sqrt(expected * (1.0 - expected) / spp) / 8.0;
    EXPECT_NEAR(m.mean, expected, 4.0 * se) << (f == &ref.mean ? "reference" : "kernel");
  }
  RegionMean r = region(ref.mean, &ref.standardError, 12, 20, 8, 16);
  EXPECT_NEAR(r.se, std::sqrt(expected * (1.0 - expected) / spp) / 8.0, 0.2 * r.se);
}

TEST(PathTracer, OpaqueSlabBetweenLightAndRegionLeavesOnlyTheEnvironment) {
  // Light straight above (superior, at 1e30 mm); an opaque black slab over a scattering
  // block. The block's pixels get nothing from the light: the same image with the light off.
  Volume v = test::shadowVolume();
  RenderParams lit = test::shadowParams(1.0), unlit = test::shadowParams(0.0);
  PathImage a = test::pathRender(v, lit, 64), b = test::pathRender(v, unlit, 64);
  // Rows 14 ... 19 of 24 see the block (z 0 ... 9 of 16 below the slab).
  RegionMean ma = region(a.radiance, nullptr, 10, 22, 14, 19);
  RegionMean mb = region(b.radiance, nullptr, 10, 22, 14, 19);
  EXPECT_NEAR(ma.mean, mb.mean, 1e-6);
  EXPECT_GT(mb.mean, 0.02);  // the environment lights it
  // Without the slab the light reaches the block: far brighter (not a vacuous test).
  RenderParams open = lit;
  open.transferFunction[4].rgba.a = open.transferFunction[5].rgba.a = 0.0;  // no slab
  PathImage c = test::pathRender(v, open, 64);
  EXPECT_GT(region(c.radiance, nullptr, 10, 22, 14, 19).mean, mb.mean + 0.1);
}

TEST(PathTracer, DeterministicForSeedAndSampleCount) {
  Volume v = test::ballVolume();
  RenderParams p = test::ballParams();
  PathImage a = test::pathRender(v, p, 8), b = test::pathRender(v, p, 8);
  EXPECT_EQ(a.image.rgba, b.image.rgba);
  EXPECT_EQ(a.radiance.rgb, b.radiance.rgb);
  // 3 + 5 samples in two calls sum in the same order as 8 in one: bitwise equal.
  Raycaster rc(test::pocl(), v);
  PathTracer pt(rc);
  Image img;
  pt.accumulate(p, 3, img);
  EXPECT_EQ(pt.accumulate(p, 5, img).samples, 8);
  EXPECT_EQ(pt.radiance().rgb, a.radiance.rgb);
  EXPECT_EQ(img.rgba, a.image.rgba);
  // Another seed: another image.
  PathTracerOptions o;
  o.seed = 2;
  pt.setOptions(o);
  pt.accumulate(p, 8, img);
  EXPECT_NE(pt.radiance().rgb, a.radiance.rgb);
}

TEST(PathTracer, KernelAgreesWithReferenceWithinItsStandardError) {
  // Multiple scattering in a ball lit by the point light and the environment. Kernel and
  // reference use different seeds (independent estimates of the same expectation) and the
  // same sample count, so their difference has standard error se_ref * sqrt(2) per pixel.
  Volume v = test::ballVolume();
  RenderParams p = test::ballParams();
  const int spp = 2048;
  PathImage k = test::pathRender(v, p, spp, 7u);
  PathReference ref = renderPathReference(v, p, spp);
  double worst = 0.0, sumK = 0.0, sumR = 0.0, var = 0.0;
  for (size_t i = 0; i < ref.mean.rgb.size(); ++i) {
    double d = double(k.radiance.rgb[i]) - ref.mean.rgb[i];
    // A pixel whose 2048 reference paths all agreed (the ball's rim, the background) has
    // a sample deviation of 0 but not a known mean: floor its error at one path in spp
    // changing by 1 (radiance here is below 1), which also covers float's summation error.
    double se = std::sqrt(2.0) * std::max(double(ref.standardError.rgb[i]), 1.0 / spp);
    sumK += k.radiance.rgb[i];
    sumR += ref.mean.rgb[i];
    var += 2.0 * double(ref.standardError.rgb[i]) * ref.standardError.rgb[i];
    worst = std::max(worst, std::abs(d) / se);
  }
  // 5 sigma: 5.7e-7 per pixel channel by chance (two-sided), 3e-4 for these 576.
  EXPECT_LT(worst, 5.0);
  double n = double(ref.mean.rgb.size());
  EXPECT_NEAR(sumK / n, sumR / n, 4.0 * std::sqrt(var) / n);
  // The ball is lit (its centre's red well above the background's 0.1): not a vacuous image.
  EXPECT_GT(ref.mean.rgb[(6 * 16 + 8) * 3], 0.5);
}

TEST(PathTracer, RestartsWhenTheFrameChanges) {
  Volume v = test::ballVolume();
  RenderParams p = test::ballParams();
  Raycaster rc(test::pocl(), v);
  PathTracer pt(rc);
  Image img;
  pt.accumulate(p, 2, img);
  EXPECT_EQ(pt.accumulate(p, 2, img).samples, 4);
  for (int change = 0; change < 5; ++change) {
    RenderParams q = p;
    if (change == 0) q.camera.azimuthDeg += 1.0;
    if (change == 1) q.transferFunction[1].rgba.a += 0.01;
    if (change == 2) q.light.position.x += 1.0;
    if (change == 3) q.clip.hi.x = 0.9;
    if (change == 4) q.width += 2;
    pt.accumulate(p, 1, img);
    EXPECT_EQ(pt.accumulate(q, 1, img).samples, 1) << "change " << change;
  }
  // The raycaster's renderer for lighting cinematic: one pass per call, counted in its stats.
  p.lighting = Lighting::Cinematic;
  FrameStats s;
  rc.rendererFor(p).render(p, img, &s);
  rc.rendererFor(p).render(p, img, &s);
  EXPECT_EQ(s.pathSamples, 2);
  EXPECT_GT(s.pathSeconds, 0.0);
  // A pick's frame with hits is the phong frame's (one hit record per pixel) and leaves
  // the accumulation alone.
  std::vector<glm::vec4> hits;
  FrameStats h;
  rc.renderWithHits(p, hits, &h);
  EXPECT_EQ(hits.size(), size_t(p.width) * size_t(p.height));
  EXPECT_EQ(h.pathSamples, 0);
  rc.rendererFor(p).render(p, img, &s);
  EXPECT_EQ(s.pathSamples, 3);
}

}  // namespace voxray
