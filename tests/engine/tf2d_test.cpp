// The 2D transfer function (issue 35, TF2D): colour and opacity over (HU, |gradient| in HU/mm),
// rectangles and triangles with a soft edge, rasterised to a table the kernels read bilinearly.
// The model's maths at known points, its files, the kernels (one ray per work-item and CPU
// packets, shaded or not, every way of computing a frame) against the double-precision
// reference renderer, and the issue's image: a boundary and a solid block of the same HU, which
// a 1D table cannot tell apart and the 2D one does.
//
// Tolerance against the reference: that of kernel_vs_reference_test.cpp and
// gradient_opacity_test.cpp (float with fast maths against double: mean absolute difference
// <= 0.5 levels, at most 0.5 % of pixels more than 3 levels apart).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "frame_setup.h"  // engine-internal: the frame's tables and view
#include "reference_sampling.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "tf2d_table.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/kernel_variant.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/engine/tf2d.h"
#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

struct Diff {
  double meanAbs = 0.0;  // in 8-bit levels
  double fractionOver3 = 0.0;
  int maxAbs = 0;
};

Diff compare(const Image& a, const Image& b) {
  Diff d;
  size_t n = size_t(a.width) * size_t(a.height), over = 0;
  double sum = 0.0;
  for (size_t i = 0; i < n; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      int e = std::abs(int(a.rgba[i * 4 + c]) - int(b.rgba[i * 4 + c]));
      sum += e;
      worst = std::max(worst, e);
    }
    d.maxAbs = std::max(d.maxAbs, worst);
    if (worst > 3) ++over;
  }
  d.meanAbs = sum / double(n * 3);
  d.fractionOver3 = double(over) / double(n);
  return d;
}

Tf2dPrimitive rect(double hu0, double hu1, double g0, double g1, glm::dvec3 rgb, double a,
                   double soft = 0.0) {
  return {Tf2dShape::Rectangle, hu0, hu1, g0, g1, rgb, a, soft};
}

Tf2dPrimitive tri(double hu0, double hu1, double g0, double g1, glm::dvec3 rgb, double a,
                  double soft = 0.0) {
  return {Tf2dShape::Triangle, hu0, hu1, g0, g1, rgb, a, soft};
}

// Stored = HU / SLOPE (intercept 0): the table must fold the slope into both axes.
Volume volumeWithSlope(double slope) {
  Volume v = test::constant({4, 4, 4}, 0);
  v.slope = slope;
  v.voxels[0] = int16_t(-2000 / slope);
  v.voxels[1] = int16_t(3000 / slope);
  return v;
}

// The anisotropic ball of kernel_vs_reference_test.cpp (1000 HU in -1000, a smooth boundary
// whose |gradient| reaches about 1000 HU/mm): gradients must be physical (per mm).
// The boundary's middle (red, soft), the boundary's upper part as a triangle (blue), and the
// flat inside faintly (white): every kind of primitive and overlap.
RenderParams tf2dBallParams() {
  RenderParams p;
  p.width = 64;
  p.height = 48;
  p.mode = Mode::Dvr;
  p.camera.azimuthDeg = 30.0;
  p.camera.elevationDeg = 20.0;
  p.camera.zoom = 1.8;
  p.stepMm = 0.5;
  // The 1D table the 2D function replaces (its shape only: where its entries sit).
  p.transferFunction = {{-1000.0, {0.0, 0.0, 0.0, 0.0}}, {1000.0, {1.0, 1.0, 1.0, 0.5}}};
  p.tf2d.primitives = {rect(-400.0, 400.0, 150.0, 1500.0, {0.9, 0.2, 0.1}, 0.25, 0.4),
                       tri(300.0, 1000.0, 0.0, 900.0, {0.1, 0.3, 1.0}, 0.2, 0.2),
                       rect(900.0, 1001.0, 0.0, 60.0, {1.0, 1.0, 1.0}, 0.04)};
  p.tf2d.gradientMax = 1500.0;
  return p;
}

}  // namespace

// One primitive at known points: the peak inside the core, the soft edge's linear fall (along
// each axis, multiplied where both fall), nothing outside; a triangle widens with |gradient|.
TEST(Tf2dModel, PrimitivesAtKnownPoints) {
  Tf2dPrimitive hard = rect(100.0, 300.0, 10.0, 50.0, {1, 0, 0}, 0.8);
  EXPECT_DOUBLE_EQ(primitiveOpacity(hard, 200.0, 30.0), 0.8);
  EXPECT_DOUBLE_EQ(primitiveOpacity(hard, 100.0, 10.0), 0.8);  // the border belongs to it
  EXPECT_DOUBLE_EQ(primitiveOpacity(hard, 99.9, 30.0), 0.0);
  EXPECT_DOUBLE_EQ(primitiveOpacity(hard, 200.0, 50.1), 0.0);
  EXPECT_DOUBLE_EQ(primitiveOpacity(hard, 200.0, 9.9), 0.0);
  // soft 0.5: the outer half of each half-extent (HU 100 ... 150, 250 ... 300; |gradient|
  // 10 ... 20, 40 ... 50) falls linearly to 0.
  Tf2dPrimitive soft = rect(100.0, 300.0, 10.0, 50.0, {1, 0, 0}, 0.8, 0.5);
  EXPECT_DOUBLE_EQ(primitiveOpacity(soft, 200.0, 30.0), 0.8);
  EXPECT_DOUBLE_EQ(primitiveOpacity(soft, 150.0, 30.0), 0.8);
  EXPECT_NEAR(primitiveOpacity(soft, 275.0, 30.0), 0.4, 1e-12);  // 3/4 out: half the peak
  EXPECT_NEAR(primitiveOpacity(soft, 275.0, 45.0), 0.2, 1e-12);  // both axes: a quarter
  EXPECT_NEAR(primitiveOpacity(soft, 300.0, 30.0), 0.0, 1e-12);
  // Triangle over HU 100 ... 300 at |gradient| 100: half-width 100 * g / 100 about HU 200.
  Tf2dPrimitive t = tri(100.0, 300.0, 0.0, 100.0, {0, 0, 1}, 0.6);
  EXPECT_DOUBLE_EQ(primitiveOpacity(t, 200.0, 50.0), 0.6);
  EXPECT_DOUBLE_EQ(primitiveOpacity(t, 249.0, 50.0), 0.6);  // half-width 50 at g 50
  EXPECT_DOUBLE_EQ(primitiveOpacity(t, 251.0, 50.0), 0.0);
  EXPECT_DOUBLE_EQ(primitiveOpacity(t, 290.0, 100.0), 0.6);
  EXPECT_DOUBLE_EQ(primitiveOpacity(t, 200.0, 0.0), 0.0);  // the apex has no width
  // Two overlapping: opacity 1 - (1 - 0.5)(1 - 0.5), colour weighted by opacity.
  Tf2d two;
  two.primitives = {rect(0, 10, 0, 10, {1, 0, 0}, 0.5), rect(0, 10, 0, 10, {0, 0, 1}, 0.5)};
  glm::dvec4 c = tf2dAt(two, 5.0, 5.0);
  EXPECT_DOUBLE_EQ(c.a, 0.75);
  EXPECT_DOUBLE_EQ(c.r, 0.5);
  EXPECT_DOUBLE_EQ(c.b, 0.5);
  EXPECT_EQ(tf2dAt(two, 20.0, 5.0), glm::dvec4(0.0));
}

// The table: 256 x 64 entries; exact (to float) at its entries, bilinear between; the value
// axis the primitives' extent with an empty column either side (so beyond it reads 0); the
// gradient axis 0 ... gmax, the top row beyond; both axes in stored units with the slope
// folded in (slope 2: HU 200 is stored 100, 30 HU/mm is 15 stored units / mm).
TEST(Tf2dModel, TheTableIsInStoredUnitsAndBilinear) {
  Tf2d tf;
  tf.primitives = {rect(100.0, 300.0, 10.0, 50.0, {1, 0.5, 0}, 0.8, 0.5)};
  tf.gradientMax = 63.0;  // one row per HU/mm
  for (double slope : {1.0, 2.0}) {
    Volume v = volumeWithSlope(slope);
    Tf2dTable t = bakeTf2dTable(tf, v);
    ASSERT_EQ(t.rgba.size(), size_t(VOXRAY_TF2D_VALUES * VOXRAY_TF2D_GRADIENTS));
    const double huStep = 200.0 / double(VOXRAY_TF2D_VALUES - 3);
    EXPECT_NEAR(v.toPhysical(t.storedLo), 100.0 - huStep, 1e-9);
    SCOPED_TRACE("slope " + std::to_string(slope));
    auto at = [&](double hu, double huPerMm) { return t.lookup(hu / slope, huPerMm / slope); };
    // At entries (column 1 + k is HU 100 + k * huStep, row j is j HU/mm): the function.
    for (int k : {1, 64, 128, 200, 254})
      for (int j : {10, 20, 30, 41, 50}) {
        double hu = 100.0 + (k - 1) * huStep;
        EXPECT_NEAR(at(hu, j).a, tf2dAt(tf, hu, j).a, 1e-6) << hu << " HU, " << j << " HU/mm";
      }
    EXPECT_NEAR(at(200.0, 30.0).a, 0.8, 1e-6);
    EXPECT_NEAR(at(200.0, 30.0).g, 0.5, 1e-6);
    // Between rows 44 and 45 (opacity 0.48 and 0.40 on the soft edge): the mean.
    EXPECT_NEAR(at(200.0, 44.5).a, 0.44, 1e-6);
    EXPECT_EQ(at(50.0, 30.0).a, 0.0);    // below the value axis
    EXPECT_EQ(at(1000.0, 30.0).a, 0.0);  // above
    EXPECT_EQ(at(200.0, 500.0).a, 0.0);  // beyond gmax: the top row (63 HU/mm, outside)
  }
  // gmax 0: the highest g1, whose row is then the top.
  tf.gradientMax = 0.0;
  EXPECT_DOUBLE_EQ(tf2dGradientMax(tf), 50.0);
  Tf2dTable t = bakeTf2dTable(tf, volumeWithSlope(1.0));
  EXPECT_NEAR(t.lookup(200.0, 1e6).a, 0.0, 1e-9);  // soft: 0 at g1, held beyond
  EXPECT_TRUE(bakeTf2dTable(Tf2d{}, volumeWithSlope(1.0)).empty());
}

// Empty-space skipping reads the 1D table: after the reduction it is above 0 wherever the 2D
// table is for some gradient (so a cell it calls empty is empty for every gradient), and 0
// where the 2D table is 0 for all of them (so skipping still skips).
TEST(Tf2dModel, TheReductionBoundsTheTableOverEveryGradient) {
  Tf2d tf;
  tf.primitives = {rect(100.0, 103.0, 400.0, 500.0, {1, 0, 0}, 0.5),  // narrower than an entry
                   tri(-600.0, -200.0, 0.0, 300.0, {0, 1, 0}, 0.3, 0.7)};
  for (double slope : {1.0, 2.0, 0.5}) {
    Volume v = volumeWithSlope(slope);
    Tf2dTable t = bakeTf2dTable(tf, v);
    Lut lut = bakeLut(TransferFunction{{{0.0, glm::dvec4(0.0)}}}, v, 300);  // coarse: 300 entries
    reduceTf2dToLut(t, lut);
    int shown = 0, empty = 0;
    for (double s = lut.storedMin; s <= lut.storedMin + 5000.0 / slope; s += 0.25) {
      double most = 0.0;
      for (double g = 0.0; g <= 600.0 / slope; g += 2.0) most = std::max(most, t.lookup(s, g).a);
      if (most > 0.0) {
        ++shown;
        ASSERT_GT(lut.lookup(s).a, 0.0) << "stored " << s << ", slope " << slope;
      } else if (lut.lookup(s).a == 0.0) {
        ++empty;
      }
    }
    EXPECT_GT(shown, 0);
    EXPECT_GT(empty, shown) << "the reduction must leave most values empty";
  }
}

// What a user types or a file holds that cannot be a 2D transfer function names the field.
TEST(Tf2dModel, BadInputNamesTheField) {
  auto message = [](auto f) {
    try {
      f();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(message([] { parseTf2d("rect:nan,300,0,10,1,0,0,1"); }).find("hu0"), std::string::npos);
  EXPECT_NE(message([] { parseTf2d("rect:100,300,-5,10,1,0,0,1"); }).find("g0"), std::string::npos);
  EXPECT_NE(message([] { parseTf2d("rect:100,100,0,10,1,0,0,1"); }).find("hu1"), std::string::npos);
  EXPECT_NE(message([] { parseTf2d("tri:100,300,10,10,1,0,0,1"); }).find("g1"), std::string::npos);
  EXPECT_NE(message([] { parseTf2d("rect:100,300,0,10,1,0,0,1.5"); }).find("opacity"),
            std::string::npos);
  EXPECT_NE(message([] { parseTf2d("rect:100,300,0,10,1,0,0,1,2"); }).find("soft"),
            std::string::npos);
  EXPECT_NE(message([] { parseTf2d("disc:1,2,3"); }).find("not a shape"), std::string::npos);
  EXPECT_NE(message([] { parseTf2d("rect:1,2,3"); }).find("8 or 9 numbers"), std::string::npos);
  std::string many;
  for (int i = 0; i < 300; ++i) many += "rect:0,1,0,1,1,1,1,1;";
  EXPECT_NE(message([&] { parseTf2d(many); }).find("at most 256"), std::string::npos);

  const std::string head =
      R"({"format": "voxray-transfer-function", "version": 1, "color": [[0, 1, 1, 1]],
          "opacity": [[0, 1]], "tf2d": )";
  auto json = [&](const std::string& tf2d) {
    return message([&] { parseVolumePropertyJson(head + tf2d + "}", "x.json"); });
  };
  const std::string prim = R"("shape": "rect", "gradient": [0, 10], "color": [1, 0, 0], )";
  EXPECT_NE(
      json(R"({"version": 1, "primitives": [{)" + prim + R"("hu": [300, 300], "opacity": 1}]})")
          .find("tf2d primitive 1 (rect): hu1"),
      std::string::npos);
  EXPECT_NE(json(R"({"version": 1, "primitives": [{"shape": "rect", "hu": [0, 1],
                 "gradient": [-1, 10], "color": [1, 0, 0], "opacity": 1}]})")
                .find("g0"),
            std::string::npos);
  EXPECT_NE(json(R"({"version": 1, "primitives": [{)" + prim + R"("hu": [0, 1]}]})")
                .find("tf2d.primitives[0].opacity is missing"),
            std::string::npos);
  EXPECT_NE(json(R"({"version": 2, "primitives": []})").find("tf2d.version"), std::string::npos);
  EXPECT_NE(json(R"({"version": 1, "gradientMax": -3, "primitives": []})").find("gradientMax"),
            std::string::npos);
  // 10^6 primitives: refused by their count before any is read.
  std::string million = R"({"version": 1, "primitives": [)";
  for (int i = 0; i < 1000000; ++i) million += i ? ",0" : "0";
  EXPECT_NE(json(million + "]}").find("tf2d.primitives has 1000000 entries; at most 256"),
            std::string::npos);
}

// Voxray's JSON keeps the 2D transfer function exactly; the flag's text too; a .vp has no place
// for it (tf convert says so), so it reads back without one.
TEST(Tf2dFiles, RoundTripsExactly) {
  VolumeProperty vp;
  vp.name = "boundaries";
  vp.color = {{-1000.0, {0, 0, 0}}, {1000.0, {1, 1, 1}}};
  vp.opacity = {{-1000.0, 0.0}, {1000.0, 0.1}};
  vp.tf2d.primitives = {rect(1.0 / 3.0, 300.1, 0.1, 123.456789, {0.1, 0.2, 0.3}, 0.7, 0.25),
                        tri(-700.0, -100.0, 7.0, 1e3 / 7.0, {1.0 / 7.0, 0.0, 1.0}, 1.0 / 3.0)};
  vp.tf2d.gradientMax = 200.0 / 3.0;
  VolumeProperty back = parseVolumePropertyJson(toVolumePropertyJson(vp), "t.json");
  EXPECT_EQ(back, vp);
  EXPECT_EQ(back.tf2d, vp.tf2d);
  EXPECT_EQ(parseTf2d(formatTf2d(vp.tf2d)), vp.tf2d);
  // The flag's text reads back as written (sessions keep it so: tests/study/session_test.cpp).
  const std::string text =
      "rect:-100.5,300.25,0,33.333333333333336,0.1,0.2,0.3,0.5,0.25;"
      "tri:200,1400,50,800,1,0.9,0.8,0.4,0;gmax:1000.5";
  EXPECT_EQ(formatTf2d(parseTf2d(text)), text);
  EXPECT_EQ(formatTf2d(parseTf2d("rect:0,1,0,1,1,1,1,1")), "rect:0,1,0,1,1,1,1,1,0");
  // A file without the section has none.
  VolumeProperty plain = vp;
  plain.tf2d = {};
  EXPECT_TRUE(parseVolumePropertyJson(toVolumePropertyJson(plain), "t.json").tf2d.empty());
  EXPECT_TRUE(parseSlicerVolumeProperty(toSlicerVolumeProperty(vp), "t.vp").tf2d.empty());
  // The render parameters take it and give it back.
  RenderParams p;
  applyVolumeProperty(p, vp);
  EXPECT_EQ(p.tf2d, vp.tf2d);
  EXPECT_EQ(volumePropertyOf(p).tf2d, vp.tf2d);
}

// Shaded or not, one ray per work-item (march.cl's dvr_segment) or packets (dvr_packet.cl and
// its shading queue), central and Sobel gradients: kernel and reference agree, and the 2D
// function changes the image (else both could ignore it and still agree).
TEST(Tf2dKernels, AgreeWithTheReference) {
  const Volume& v = test::anisotropicBall();
  for (bool shading : {false, true})
    for (Gradient op : {Gradient::Central, Gradient::Sobel}) {
      RenderParams p = tf2dBallParams();
      p.shading = shading;
      p.gradient = op;
      Image ref = renderReference(v, p);
      RenderParams off = p;
      off.tf2d = {};
      Diff changed = compare(ref, renderReference(v, off));
      EXPECT_GT(changed.meanAbs, 5.0) << "the 2D function must show";
      for (bool packets : {true, false}) {
        Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
        RaycasterOptions o = rc.options();
        o.packets = packets;
        rc.setOptions(o);
        Image gpu = rc.render(p);
        Diff d = compare(gpu, ref);
        std::string what =
            test::variantDescription(p, packets) + " (max " + std::to_string(d.maxAbs) + ")";
        EXPECT_NE(rc.variantOptions(p).find("-D TF2D=1"), std::string::npos) << what;
        EXPECT_LE(d.meanAbs, 0.5) << what;
        EXPECT_LE(d.fractionOver3, 0.005) << what;
      }
    }
}

// The other ways a frame is computed (none changes the image): 8-lane packets, no empty-space
// skipping, the uber kernel, z slabs, image3d_t storage where the device has it. Empty-space
// skipping stays exact: the frame with it is the frame without it (to a level of rounding), so
// no cell it leaps held a sample the 2D table shows at some gradient.
TEST(Tf2dKernels, EveryWayOfComputingAgreesWithTheReference) {
  const Volume& v = test::anisotropicBall();
  RenderParams p = tf2dBallParams();
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
    Diff d = compare(rc.render(p), ref);
    std::string what = std::string(w.name) + " (max " + std::to_string(d.maxAbs) + ")";
    if (w.options.maxSlabBytes) {
      EXPECT_GT(rc.slabCount(), 1) << what;
    }
    EXPECT_LE(d.meanAbs, 0.5) << what;
    EXPECT_LE(d.fractionOver3, 0.005) << what;
  }
  for (bool packets : {true, false}) {
    Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
    RaycasterOptions o = rc.options();
    o.packets = packets;
    rc.setOptions(o);
    Image leaping = rc.render(p);
    o.emptySpaceSkipping = false;
    rc.setOptions(o);
    Diff d = compare(leaping, rc.render(p));
    EXPECT_LE(d.maxAbs, 1) << test::variantDescription(p, packets)
                           << ": with and without empty-space skipping";
  }
}

// Packets classify 2D samples from a queue (classify_queue.cl), except with hit output (the dvr
// pick), labels or an overlay, which classify in place (dvr_tf2dN): the two agree.
TEST(Tf2dKernels, ThePacketsQueueAndInPlaceAgree) {
  const Volume& v = test::anisotropicBall();
  for (bool shading : {false, true}) {
    RenderParams p = tf2dBallParams();
    p.shading = shading;
    Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
    Image queued = rc.render(p);
    std::vector<glm::vec4> hits;
    Image inPlace = rc.renderWithHits(p, hits);
    EXPECT_EQ(hits.size(), size_t(p.width * p.height));
    Diff d = compare(queued, inPlace);
    EXPECT_LE(d.maxAbs, 1) << test::variantDescription(p, true)
                           << ": queued against in place (hit output)";
  }
}

// A 2D table that is the 1D table (one rectangle over every value and gradient, the 1D
// table's constant colour and opacity) switches TF2D on and changes no pixel in phong, shadows
// or ao: their light grid moves behind the 2D table, built from the 1D table it becomes (the
// largest over gradient: here the same), and the packets' queue shades with the gradient it
// kept and the colour it looks up at (value, |gradient|).
TEST(Tf2dKernels, TheSameTableChangesNothingInAnyLighting) {
  const Volume& v = test::anisotropicBall();
  for (Lighting lighting : {Lighting::Phong, Lighting::Shadows, Lighting::Ao})
    for (bool packets : {true, false}) {
      RenderParams off = tf2dBallParams();
      off.tf2d = {};
      off.transferFunction = {{0.0, {0.8, 0.6, 0.4, 0.06}}};
      off.lighting = lighting;
      RenderParams on = off;
      on.tf2d.primitives = {rect(-1001.0, 1001.0, 0.0, 2000.0, {0.8, 0.6, 0.4}, 0.06)};
      Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
      RaycasterOptions o = rc.options();
      o.packets = packets;
      rc.setOptions(o);
      Image a = rc.render(off), b = rc.render(on), c = rc.render(off);
      std::string what = test::variantDescription(on, packets) + " " + toString(lighting);
      EXPECT_NE(rc.variantOptions(on), rc.variantOptions(off)) << what;
      Diff d = compare(a, b);
      EXPECT_LE(d.maxAbs, 1) << what;  // the same sums; fast maths may round one level apart
      EXPECT_EQ(a.rgba, c.rgba) << what << ": back without it, byte for byte";
    }
}

// Issue 35's image: a ball of 600 HU in 0 HU, whose boundary passes through 150 ... 450 HU at
// 300 HU/mm (central differences of a 0 -> 600 step between voxels), beside a uniform slab of
// 300 HU, whose inside has |gradient| 0 and whose faces (0 -> 300) reach 150 HU/mm, its edges
// 212 and its corners 260 HU/mm (two and three faces' 150). A 1D table that shows 150 ... 450 HU
// shows the slab (and hiding it hides the boundary); the 2D table over 150 ... 450 HU at
// 270 ... 1000 HU/mm shows the ball's boundary and no pixel of the slab. (The window spans half a
// voxel of the boundary's trilinear ramp: a 0.25 mm step samples it at every crossing.)
// Orthographic, unshaded, black background: a pixel's colour is the table's green.
TEST(Tf2dImage, ShowsTheBoundaryAndNotTheSlabOfTheSameHu) {
  Volume v = test::constant({64, 64, 64}, 0);
  const glm::dvec3 centre(46.0, 32.0, 32.0);
  const double radius = 10.0;
  for (int z = 0; z < 64; ++z)
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        if (glm::length(glm::dvec3(x, y, z) - centre) <= radius) v.voxels[v.index(x, y, z)] = 600;
        if (x >= 6 && x <= 28 && y >= 12 && y <= 52 && z >= 10 && z <= 54)
          v.voxels[v.index(x, y, z)] = 300;
      }
  RenderParams p;
  p.width = p.height = 128;
  p.mode = Mode::Dvr;
  p.shading = false;
  p.background = glm::dvec3(0.0);
  p.camera.projection = Projection::Orthographic;
  p.stepMm = 0.25;
  p.transferFunction = {{140.0, {0.0, 1.0, 0.0, 0.0}},
                        {150.0, {0.0, 1.0, 0.0, 0.5}},
                        {450.0, {0.0, 1.0, 0.0, 0.5}},
                        {460.0, {0.0, 1.0, 0.0, 0.0}}};
  RenderParams two = p;
  two.tf2d.primitives = {rect(150.0, 450.0, 270.0, 1000.0, {0.0, 1.0, 0.0}, 0.5)};

  // Each pixel's ray: through the ball (passing half a voxel inside its radius), by its rim (up
  // to 1.5 voxels outside: partly), through the slab only (its middle: 2 voxels in from its
  // sides as seen), or neither.
  FrameSetup s = makeFrameSetup(v, p);
  enum Kind { Ball, Rim, Slab, Neither };
  std::vector<Kind> kind(size_t(p.width * p.height), Neither);
  int ballPixels = 0, slabPixels = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      PixelRay r;
      if (!pixelRay(s.view, x, y, p.width, p.height, r)) continue;
      glm::dvec3 d = glm::normalize(r.dv), w = centre - r.ov;
      double dist = glm::length(w - glm::dot(w, d) * d);
      // Where the ray is at the slab's middle depth (y = 32): inside its x and z by 2 voxels?
      glm::dvec3 mid = r.ov + d * ((32.0 - r.ov.y) / d.y);
      Kind& k = kind[size_t(y * p.width + x)];
      if (dist <= radius - 0.5)
        k = Ball, ++ballPixels;
      else if (dist <= radius + 1.5)
        k = Rim;
      else if (mid.x >= 8 && mid.x <= 26 && mid.z >= 12 && mid.z <= 52)
        k = Slab, ++slabPixels;
    }
  ASSERT_GT(ballPixels, 300);
  ASSERT_GT(slabPixels, 700);

  // Pixels of each kind whose green is above 8 (of 255), and the brightest.
  struct Count {
    int ballShown = 0, slabShown = 0, elsewhereShown = 0, slabMax = 0, ballMax = 0;
  };
  auto count = [&](const Image& im) {
    Count c;
    for (size_t i = 0; i < kind.size(); ++i) {
      int g = im.rgba[i * 4 + 1];
      bool shown = g > 8;
      if (kind[i] == Ball) c.ballShown += shown, c.ballMax = std::max(c.ballMax, g);
      if (kind[i] == Slab) c.slabShown += shown, c.slabMax = std::max(c.slabMax, g);
      if (kind[i] == Neither) c.elsewhereShown += shown;
    }
    return c;
  };
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  for (bool packets : {true, false}) {
    RaycasterOptions o = rc.options();
    o.packets = packets;
    rc.setOptions(o);
    for (bool reference : {false, true}) {
      std::string what = reference ? "reference" : packets ? "packets" : "one ray per work-item";
      Image im1 = reference ? renderReference(v, p) : rc.render(p);
      Image im2 = reference ? renderReference(v, two) : rc.render(two);
      Count one = count(im1);
      Count twoD = count(im2);
      SCOPED_TRACE(testing::Message()
                   << what << ": 1D ball " << one.ballShown << "/" << ballPixels << " slab "
                   << one.slabShown << "/" << slabPixels << " (max " << one.slabMax << "); 2D ball "
                   << twoD.ballShown << " (max " << twoD.ballMax << ") slab " << twoD.slabShown
                   << " (max " << twoD.slabMax << ") elsewhere " << twoD.elsewhereShown);
      // 1D: the slab (41 voxels deep at 0.5 a voxel) is opaque green; the ball's boundary shows.
      EXPECT_EQ(one.slabShown, slabPixels);
      EXPECT_GE(one.slabMax, 250);
      EXPECT_EQ(one.ballShown, ballPixels);
      // 2D: the same boundary shows on every ray through the ball (each crosses it twice), the
      // slab on none, nor anything else.
      EXPECT_EQ(twoD.ballShown, ballPixels);
      EXPECT_GE(twoD.ballMax, 100);
      EXPECT_EQ(twoD.slabShown, 0);
      EXPECT_EQ(twoD.slabMax, 0);
      EXPECT_EQ(twoD.elsewhereShown, 0);
    }
  }
}

}  // namespace voxray
