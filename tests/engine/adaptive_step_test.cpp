// Adaptive dvr steps (RenderParams::adaptiveError; kernels/empty_space/classify.cl,
// adaptive_level): where the table varies within the bound E over the values around a macro cell,
// segments whose midpoint lies in it are 2 or 4 base steps long, their opacity corrected for it.
// The stated bound: each long segment changes the composite by at most E times the transmittance in
// front of it (opacity, and each colour channel before shading). Where the table is constant over
// the values a cell holds the bound is 0: the long segment's transmittance (1 - a)^(4h) is
// that of its four short ones, so only float rounding (at most one 8-bit level) remains.
#include <gtest/gtest.h>

#include <cstdint>

#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/raycaster.h"

namespace voxray {

namespace {

constexpr double kBound = 0.01;  // E: the per-segment bound the tests render with

// Air (-1000) with a slab of `value` HU across x and y, z in [10, 38).
Volume slab(int16_t value) {
  Volume v = test::constant({48, 44, 48}, -1000);
  for (int z = 10; z < 38; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x) v.voxels[v.index(x, y, z)] = value;
  return v;
}

// Noise between -400 and 600 HU in every voxel: every macro cell spans most of it.
Volume noise(glm::ivec3 dims) {
  Volume n = test::constant(dims, 0);
  for (int z = 0; z < n.dims.z; ++z)
    for (int y = 0; y < n.dims.y; ++y)
      for (int x = 0; x < n.dims.x; ++x) {
        uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(z) * 83492791u;
        h = (h ^ (h >> 13)) * 0x5bd1e995u;
        n.voxels[n.index(x, y, z)] = int16_t(-400 + int((h >> 8) % 1001u));
      }
  return n;
}

// Flat between 0 and 100 HU (a slab of 50 HU is homogeneous), steep above.
std::vector<ControlPoint> table() {
  return {{-1000.0, {0.0, 0.0, 0.0, 0.0}}, {-200.0, {0.8, 0.5, 0.4, 0.0}},
          {0.0, {0.8, 0.5, 0.4, 0.05}},    {100.0, {0.8, 0.5, 0.4, 0.05}},
          {300.0, {1.0, 1.0, 0.9, 0.6}},   {3000.0, {1.0, 1.0, 1.0, 1.0}}};
}

RenderParams adaptiveStepParams(double adaptive) {
  RenderParams p;
  p.width = 64;
  p.height = 48;
  p.mode = Mode::Dvr;
  p.transferFunction = table();
  p.camera.azimuthDeg = 30.0;
  p.camera.elevationDeg = 20.0;
  p.adaptiveError = adaptive;
  return p;
}

using test::kPerRay;

Image renderCountingSamples(const Volume& v, const RenderParams& p, int lanes, double* samples) {
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  RaycasterOptions o;
  o.countSamples = true;
  o.packets = lanes != kPerRay;
  o.packetLanes = lanes == kPerRay ? 0 : lanes;
  rc.setOptions(o);
  FrameStats stats;
  Image image = rc.render(p, &stats);
  *samples = stats.samples;
  return image;
}

}  // namespace

// A homogeneous slab: long steps inside it (about a quarter of the samples there), and the
// image of fixed steps within the bound, which is 0 here (one level of rounding).
TEST(AdaptiveStep, HomogeneousSlabWithinTheBound) {
  Volume v = slab(50);
  for (int lanes : {kPerRay, 8, 16}) {
    SCOPED_TRACE(testing::Message() << "lanes " << lanes);
    double fixedSamples = 0.0, adaptiveSamples = 0.0;
    Image fixed = renderCountingSamples(v, adaptiveStepParams(0.0), lanes, &fixedSamples);
    Image adaptive = renderCountingSamples(v, adaptiveStepParams(kBound), lanes, &adaptiveSamples);
    EXPECT_LE(test::maxDiff(fixed, adaptive), 1);
    // Not a blank test: the slab shows (many pixels off the black background).
    int shown = 0;
    for (size_t i = 0; i < fixed.rgba.size(); i += 4) shown += fixed.rgba[i] > 20;
    EXPECT_GT(shown, 400);  // 653 of the 3072 pixels
    // Cells whose values (with the next cell's) reach the slab's faces keep the base
    // step; the 28-voxel slab's middle 16 or so do not: well under 60 % of the samples
    // remain.
    EXPECT_LT(adaptiveSamples, 0.6 * fixedSamples);
  }
}

// Where the table varies over every cell (noise across a steep ramp of opacity), no cell
// allows a longer step: the same samples, the same image.
TEST(AdaptiveStep, VaryingTableKeepsTheBaseStep) {
  Volume v = noise({40, 36, 32});
  for (int lanes : {kPerRay, 8, 16}) {
    SCOPED_TRACE(testing::Message() << "lanes " << lanes);
    double fixedSamples = 0.0, adaptiveSamples = 0.0;
    Image fixed = renderCountingSamples(v, adaptiveStepParams(0.0), lanes, &fixedSamples);
    Image adaptive = renderCountingSamples(v, adaptiveStepParams(kBound), lanes, &adaptiveSamples);
    EXPECT_EQ(test::maxDiff(fixed, adaptive), 0);
    EXPECT_EQ(adaptiveSamples, fixedSamples);
    EXPECT_GT(fixedSamples, 1000.0);
  }
}

// A graded volume (a ramp along x from -150 to 132 HU: the table's gentle part takes long
// segments, its steep part the base step): one ray per work-item and packets of either
// width take long segments at different places (packets leap only when all their lanes
// can), so their images differ, each within the bound of the fixed steps' image.
TEST(AdaptiveStep, PacketsAndOneRayPerWorkItemAgree) {
  Volume v = test::rampX({48, 44, 48}, -150.0, 6.0);
  RenderParams fixedParams = adaptiveStepParams(0.0), adaptiveParams = adaptiveStepParams(0.1);
  double samples = 0.0, fixedSamples = 0.0;
  Image perRay = renderCountingSamples(v, adaptiveParams, kPerRay, &samples);
  Image fixed = renderCountingSamples(v, fixedParams, kPerRay, &fixedSamples);
  // Measured: 39 % of the fixed steps' samples, every image within one level of the others
  // (float rounding; the bound allows more, each long segment at most 0.1 of the
  // transmittance in front of it, but along this ramp the table is nearly linear, where a
  // midpoint sample errs little).
  EXPECT_LE(test::maxDiff(perRay, fixed), 2);
  EXPECT_LT(samples, 0.6 * fixedSamples);
  for (int lanes : {8, 16}) {
    SCOPED_TRACE(testing::Message() << "lanes " << lanes);
    Image packets = renderCountingSamples(v, adaptiveParams, lanes, &samples);
    EXPECT_LE(test::maxDiff(packets, perRay), 2);
    EXPECT_LE(test::maxDiff(packets, fixed), 2);
    EXPECT_LT(samples, 0.6 * fixedSamples);
  }
}

// A bound of 0 turns it off, and so does dvr without opacity correction (long segments
// need it): the variant has no adaptive code.
TEST(AdaptiveStep, OnlyWithABoundAndOpacityCorrection) {
  Volume v = slab(50);  // the raycaster keeps a reference
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  FrameStats stats;
  RenderParams p = adaptiveStepParams(kBound);
  rc.render(p, &stats);
  EXPECT_NE(stats.variant.find("ADAPTIVE=1"), std::string::npos) << stats.variant;
  p.opacityCorrection = false;
  rc.render(p, &stats);
  EXPECT_NE(stats.variant.find("ADAPTIVE=0"), std::string::npos) << stats.variant;
  rc.render(adaptiveStepParams(0.0), &stats);
  EXPECT_NE(stats.variant.find("ADAPTIVE=0"), std::string::npos) << stats.variant;
}

}  // namespace voxray
