// The gradient-magnitude opacity (issue 35, GRADIENT_OPACITY): dvr opacity times a factor of
// |gradient| in HU/mm. The kernels (one ray per work-item and CPU packets, shaded or not)
// against the double-precision reference renderer, and a scene where it shows what a 1D
// transfer function cannot: the inside of a homogeneous block fades, so an object behind it
// appears, while the block's faces and a small ball of the same value stay.
//
// Tolerance against the reference: that of kernel_vs_reference_test.cpp (float with fast
// maths against double: mean absolute difference <= 0.5 levels, at most 0.5 % of pixels more
// than 3 levels apart), and at the scene's chosen pixels 3 levels.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ball_scene.h"
#include "frame_setup.h"  // engine-internal: the frame's view, for the pixels of chosen points
#include "gradient_table.h"
#include "reference_sampling.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/kernel_variant.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

// A table that shows the ball's inside (1000 HU) as well as its boundary, and a gradient
// opacity that fades what is flat: 0 below 100 HU/mm, 1 from 600 HU/mm (the boundary's
// |gradient| reaches about 1000 HU/mm).
RenderParams gradientOpacityParams() {
  RenderParams p = test::ballView(Mode::Dvr);
  p.stepMm = 0.5;
  p.transferFunction = {{-1000.0, {0.0, 0.0, 0.0, 0.0}},
                        {0.0, {0.9, 0.5, 0.3, 0.05}},
                        {1000.0, {1.0, 0.95, 0.8, 0.08}}};
  p.gradientOpacity = {{100.0, 0.0}, {600.0, 1.0}};
  return p;
}

// The pixel whose ray passes closest to voxel position q.
glm::ivec2 pixelOf(const Volume& v, const RenderParams& p, const glm::dvec3& q) {
  FrameSetup s = makeFrameSetup(v, p);
  glm::ivec2 best(-1);
  double bestD = 1e30;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      PixelRay r;
      if (!pixelRay(s.view, x, y, p.width, p.height, r)) continue;
      glm::dvec3 d = glm::normalize(r.dv), w = q - r.ov;
      double dist = glm::length(w - glm::dot(w, d) * d);
      if (dist < bestD) bestD = dist, best = {x, y};
    }
  return best;
}

glm::ivec3 rgbAt(const Image& im, glm::ivec2 px) {
  size_t i = (size_t(px.y) * size_t(im.width) + size_t(px.x)) * 4;
  return {im.rgba[i], im.rgba[i + 1], im.rgba[i + 2]};
}

}  // namespace

// The table the kernels read: factors over |gradient| in stored units per mm, the slope
// folded in (a slope of 2 HU per stored unit: 50 stored units / mm are 100 HU/mm), linear
// between points, a repeated point a step, the ends held.
TEST(GradientOpacity, TheTableIsInHuPerMm) {
  GradientTable t = bakeGradientTable({{0.0, 0.0}, {100.0, 0.5}, {200.0, 0.5}, {200.0, 1.0}}, 2.0);
  ASSERT_EQ(t.factor.size(), size_t(VOXRAY_GRADIENT_TABLE_ENTRIES));
  // 256 entries over 0 ... 200 HU/mm: linear pieces are exact at the entries, a bend
  // between two entries is cut by at most half an entry's change (here 0.002).
  EXPECT_DOUBLE_EQ(t.lookup(0.0), 0.0);
  EXPECT_NEAR(t.lookup(25.0), 0.25, 1e-6);  // 50 HU/mm
  EXPECT_NEAR(t.lookup(50.0), 0.5, 2e-3);   // 100 HU/mm: the bend
  EXPECT_NEAR(t.lookup(75.0), 0.5, 1e-6);
  EXPECT_NEAR(t.lookup(100.0), 1.0, 1e-9);  // the step at 200 HU/mm: the upper point
  EXPECT_DOUBLE_EQ(t.lookup(1e6), 1.0);
  EXPECT_TRUE(bakeGradientTable({}, 1.0).factor.empty());
  EXPECT_DOUBLE_EQ(bakeGradientTable({}, 1.0).lookup(10.0), 1.0);  // off
  // One point: its factor everywhere.
  EXPECT_DOUBLE_EQ(bakeGradientTable({{0.0, 0.3}}, 1.0).lookup(123.0), double(0.3f));
}

// Shaded or not, one ray per work-item (march.cl's dvr_segment) or packets (dvr_packet.cl and
// its shading queue), with empty-space skipping (the default): kernel and reference agree,
// and the factor changes the image (else both could ignore it and still agree).
TEST(GradientOpacity, KernelsAgreeWithTheReference) {
  const Volume& v = test::anisotropicBall();
  for (bool shading : {false, true})
    for (Gradient op : {Gradient::Central, Gradient::Sobel}) {
      RenderParams p = gradientOpacityParams();
      p.shading = shading;
      p.gradient = op;
      Image ref = renderReference(v, p);
      RenderParams off = p;
      off.gradientOpacity.clear();
      test::ImageDiff changed = test::compareImages(ref, renderReference(v, off));
      EXPECT_GT(changed.meanAbs, 5.0) << "the factor must show";
      for (bool packets : {true, false}) {
        Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
        RaycasterOptions o = rc.options();
        o.packets = packets;
        rc.setOptions(o);
        Image gpu = rc.render(p);
        test::ImageDiff d = test::compareImages(gpu, ref);
        std::string what =
            test::variantDescription(p, packets) + " (max " + std::to_string(d.maxAbs) + ")";
        EXPECT_NE(rc.variantOptions(p).find("-D GRADIENT_OPACITY=1"), std::string::npos) << what;
        EXPECT_LE(d.meanAbs, 0.5) << what;
        EXPECT_LE(d.fractionOver3, 0.005) << what;
      }
    }
}

// The other ways a frame is computed (none changes the image): 8-lane packets, no empty-space
// skipping, the uber kernel, z slabs, image3d_t storage where the device has it.
TEST(GradientOpacity, EveryWayOfComputingAgreesWithTheReference) {
  const Volume& v = test::anisotropicBall();
  RenderParams p = gradientOpacityParams();
  Image ref = renderReference(v, p);
  struct Way {
    const char* name;
    VolumeStorage storage;
    RaycasterOptions options;
  };
  std::vector<Way> ways(5, {"", VolumeStorage::Buffer, {}});
  ways[0].name = "8-lane packets";
  ways[0].options.packetLanes = 8;
  ways[1].name = "no empty-space skipping";
  ways[1].options.emptySpaceSkipping = false;
  ways[2].name = "uber";
  ways[2].options.kernel = RaycasterOptions::Kernel::Uber;
  ways[3].name = "z slabs";
  ways[3].options.maxSlabBytes = 40 * 36 * 8 * sizeof(int16_t);
  ways[4].name = "image3d_t";
  ways[4].storage = VolumeStorage::Image3d;
  for (const Way& w : ways) {
    if (w.storage == VolumeStorage::Image3d && !test::pocl().device().imageSupport) continue;
    Raycaster rc(test::pocl(), v, w.storage);
    rc.setOptions(w.options);
    test::ImageDiff d = test::compareImages(rc.render(p), ref);
    std::string what = std::string(w.name) + " (max " + std::to_string(d.maxAbs) + ")";
    if (w.options.maxSlabBytes) EXPECT_GT(rc.slabCount(), 1) << what;
    EXPECT_LE(d.meanAbs, 0.5) << what;
    EXPECT_LE(d.fractionOver3, 0.005) << what;
  }
}

// A factor of 1 everywhere switches GRADIENT_OPACITY on and changes no pixel: shadows and ao
// read their light grid behind the gradient table (where it moves with it), the packets'
// shading queue shades with the gradient it stored.
TEST(GradientOpacity, FactorOneChangesNothingInAnyLighting) {
  const Volume& v = test::anisotropicBall();
  for (Lighting lighting : {Lighting::Phong, Lighting::Shadows, Lighting::Ao})
    for (bool packets : {true, false}) {
      RenderParams off = gradientOpacityParams();
      off.gradientOpacity.clear();
      off.lighting = lighting;
      RenderParams on = off;
      on.gradientOpacity = {{0.0, 1.0}};
      Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
      RaycasterOptions o = rc.options();
      o.packets = packets;
      rc.setOptions(o);
      Image a = rc.render(off), b = rc.render(on), c = rc.render(off);
      std::string what = test::variantDescription(on, packets) + " " + toString(lighting);
      EXPECT_NE(rc.variantOptions(on), rc.variantOptions(off)) << what;
      test::ImageDiff d = test::compareImages(a, b);
      EXPECT_LE(d.maxAbs, 1) << what;  // the same sums; fast maths may round one level apart
      EXPECT_EQ(a.rgba, c.rgba) << what << ": back without it, byte for byte";
    }
}

// Issue 35's point: a 1D table cannot tell the inside of a block from its faces, the gradient
// opacity can. A slab of 500 HU (24 voxels deep) hides a green block of 1500 HU behind it
// from a 1D table; with the gradient opacity the slab's inside fades (|gradient| 0 there) and
// the green block shows through, while the slab's faces and a small ball of the same 500 HU
// beside it (all boundary) stay red. Orthographic, unshaded: colours are the table's.
TEST(GradientOpacity, HidesTheInsideOfABlockThatA1DTableCannot) {
  Volume v;
  v.dims = {48, 48, 48};
  v.voxels.assign(v.voxelCount(), -1000);
  auto fill = [&](glm::ivec3 lo, glm::ivec3 hi, int16_t value) {
    for (int z = lo.z; z <= hi.z; ++z)
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) v.voxels[v.index(x, y, z)] = value;
  };
  // The camera looks from anterior along +y (index y grows toward posterior).
  fill({10, 8, 10}, {34, 31, 34}, 500);    // the slab, in front
  fill({18, 36, 18}, {26, 42, 26}, 1500);  // the green block, behind it
  const glm::dvec3 ballCentre(41.0, 20.0, 22.0);
  for (int z = 0; z < 48; ++z)
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 48; ++x)
        if (glm::length(glm::dvec3(x, y, z) - ballCentre) <= 3.5) v.voxels[v.index(x, y, z)] = 500;

  RenderParams p;
  p.width = p.height = 96;
  p.mode = Mode::Dvr;
  p.shading = false;
  p.camera.projection = Projection::Orthographic;
  p.stepMm = 0.5;
  p.transferFunction = {{200.0, {1.0, 0.0, 0.0, 0.0}},  {300.0, {1.0, 0.0, 0.0, 0.1}},
                        {700.0, {1.0, 0.0, 0.0, 0.1}},  {800.0, {0.0, 1.0, 0.0, 0.0}},
                        {1200.0, {0.0, 1.0, 0.0, 0.0}}, {1300.0, {0.0, 1.0, 0.0, 1.0}}};
  RenderParams go = p;
  go.gradientOpacity = {{50.0, 0.0}, {200.0, 1.0}};

  const glm::ivec2 behind = pixelOf(v, p, {22.0, 24.0, 22.0});  // slab, then the green block
  const glm::ivec2 slabOnly = pixelOf(v, p, {13.0, 20.0, 31.0});
  const glm::ivec2 ball = pixelOf(v, p, ballCentre);
  ASSERT_NE(behind, slabOnly);
  ASSERT_NE(ball.x, -1);

  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  for (const RenderParams* q : {&p, &go}) {
    Image ref = renderReference(v, *q);
    for (bool packets : {true, false}) {
      RaycasterOptions o = rc.options();
      o.packets = packets;
      rc.setOptions(o);
      Image gpu = rc.render(*q);
      for (glm::ivec2 px : {behind, slabOnly, ball}) {
        glm::ivec3 a = rgbAt(gpu, px), b = rgbAt(ref, px);
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(a[c], b[c], 3)
              << test::variantDescription(*q, packets) << " pixel " << px.x << "," << px.y;
      }
    }
  }
  Image flat = renderReference(v, p), withGo = renderReference(v, go);
  const glm::ivec3 flatBehind = rgbAt(flat, behind), goBehind = rgbAt(withGo, behind);
  const glm::ivec3 flatSlab = rgbAt(flat, slabOnly), goSlab = rgbAt(withGo, slabOnly);
  const glm::ivec3 flatBall = rgbAt(flat, ball), goBall = rgbAt(withGo, ball);
  SCOPED_TRACE(testing::Message() << "1D: behind " << flatBehind.r << "," << flatBehind.g
                                  << " slab " << flatSlab.r << " ball " << flatBall.r
                                  << "; gradient opacity: behind " << goBehind.r << ","
                                  << goBehind.g << " slab " << goSlab.r << " ball " << goBall.r);
  // 1D: the slab (24 voxels at 0.1 a voxel: 1 - 0.9^24 = 0.92 of 255 = 235, less where its
  // faces ramp up) hides the green block (0.08 of 255 = 20 left for it). Seen: red 232,
  // green 23.
  EXPECT_GE(flatSlab.r, 225);
  EXPECT_LE(flatSlab.r, 240);
  EXPECT_LE(flatBehind.g, 30);
  // Gradient opacity: only the slab's two faces are left (seen: red 47), the same in front of
  // the green block, which shows through (seen: 208).
  EXPECT_GE(goBehind.g, 180);
  EXPECT_GE(goSlab.r, 30);  // the faces still show
  EXPECT_LE(goSlab.r, 70);
  EXPECT_NEAR(goBehind.r, goSlab.r, 3);
  // The small ball is nearly all boundary: it keeps twice the share of its red the slab keeps
  // (seen: 48 of 119 against 47 of 232).
  EXPECT_GE(double(goBall.r) / flatBall.r, 1.5 * double(goSlab.r) / flatSlab.r);
}

}  // namespace voxray
