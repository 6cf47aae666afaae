// Empty-space skipping, the uber kernel and ray packets on CPUs are speed-ups only:
// the image must be the one the plain specialised kernel makes. ESS leaps only samples
// that cannot change a pixel, in the same order and with the same positions, so frames
// agree exactly; the uber kernel and the one-ray-per-work-item kernel are different
// compilations of the same algorithm (packets also skip the rest of a voxel cell that
// cannot hold the iso range), so they may differ by float contraction: at most one 8-bit
// level.
#include <gtest/gtest.h>

#include <tuple>

#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/kernel_variant.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

// A small ball in a large empty box, so most cells are empty and rays leap them.
const Volume& sparseVolume() {
  static Volume v = test::ball({64, 56, 40}, 10.0, 1000.0, -1000.0, {1.0, 1.1, 1.6});
  return v;
}

RenderParams essParams(Mode mode, Gradient g, Interp interp, bool jitter) {
  RenderParams p;
  p.width = 80;
  p.height = 60;
  p.mode = mode;
  p.gradient = g;
  p.interp = interp;
  p.jitter = jitter;
  p.isoLo = 0.0;
  p.camera.azimuthDeg = 35.0;
  p.camera.elevationDeg = 25.0;
  if (mode == Mode::Dvr) p.preset = "CT-Bone";
  return p;
}

// Noise from -400 to 600 with two bright blobs: along a ray the running maximum keeps
// rising, so mip's skipping (cells and voxel cells that cannot raise it, or that stay
// below the window) decides often, both ways.
Volume noisy(glm::ivec3 dims) {
  Volume n = test::constant(dims, 0);
  glm::dvec3 blobs[2] = {glm::dvec3(dims) * 0.3, glm::dvec3(dims) * 0.7};
  for (int z = 0; z < n.dims.z; ++z)
    for (int y = 0; y < n.dims.y; ++y)
      for (int x = 0; x < n.dims.x; ++x) {
        uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(z) * 83492791u;
        h = (h ^ (h >> 13)) * 0x5bd1e995u;
        double value = -400.0 + 1000.0 * double((h >> 8) & 0xffff) / 65535.0;
        for (glm::dvec3 c : blobs)
          if (glm::length(glm::dvec3(x, y, z) - c) < 4.0) value = 1500.0 - 20.0 * (x % 40);
        n.voxels[n.index(x, y, z)] = int16_t(value);
      }
  return n;
}

const Volume& noisyVolume() {
  static Volume v = noisy({48, 40, 36});
  return v;
}

// Long along x: a ray along it crosses more macro cells than a mip packet's walk keeps
// (kernels/march/mip_packet.cl, MIP_WALK), so it takes the in-order loop.
const Volume& longVolume() {
  static Volume v = noisy({2000, 12, 12});  // 500 cells along x
  return v;
}

// lanes: rays per CPU packet (8 or 16), 0 the raycaster's choice, kPerRay for none.
using test::kPerRay;

Image renderEmptySpace(RaycasterOptions::Kernel k, bool ess, const RenderParams& p, int lanes = 0,
                       const Volume& volume = sparseVolume()) {
  Raycaster rc(test::pocl(), volume, VolumeStorage::Buffer);
  RaycasterOptions o;
  o.kernel = k;
  o.emptySpaceSkipping = ess;
  o.packets = lanes != kPerRay;
  o.packetLanes = lanes == kPerRay ? 0 : lanes;
  rc.setOptions(o);
  return rc.render(p);
}

}  // namespace

using EssCase = std::tuple<Mode, Gradient, Interp, bool>;
class EmptySpace : public ::testing::TestWithParam<EssCase> {};

std::string variantTestName(const ::testing::TestParamInfo<EssCase>& info) {
  auto [mode, g, interp, jitter] = info.param;
  return kernelVariantName(essParams(mode, g, interp, jitter));
}

TEST_P(EmptySpace, SkippingChangesNoPixel) {
  auto [mode, g, interp, jitter] = GetParam();
  RenderParams p = essParams(mode, g, interp, jitter);
  using K = RaycasterOptions::Kernel;
  Image plain = renderEmptySpace(K::Specialised, false, p, kPerRay);
  EXPECT_EQ(test::maxDiff(plain, renderEmptySpace(K::Specialised, true, p, kPerRay)), 0);
  EXPECT_LE(test::maxDiff(plain, renderEmptySpace(K::Uber, true, p)), 1);
  // Every mode runs ray packets on this CPU device, of either width; they must agree with
  // one ray per work-item, and skipping must not change their pixels.
  for (int lanes : {8, 16}) {
    SCOPED_TRACE(testing::Message() << lanes << " lanes");
    Image packets = renderEmptySpace(K::Specialised, false, p, lanes);
    EXPECT_LE(test::maxDiff(plain, packets), 1);
    EXPECT_EQ(test::maxDiff(packets, renderEmptySpace(K::Specialised, true, p, lanes)), 0);
  }
}

// Every mode; gradient, interpolation and jitter vary together (each kernel build on PoCL
// takes seconds, so not every combination).
INSTANTIATE_TEST_SUITE_P(Variants, EmptySpace,
                         ::testing::Combine(::testing::Values(Mode::Iso, Mode::Dvr, Mode::Mip),
                                            ::testing::Values(Gradient::Central),
                                            ::testing::Values(Interp::Linear),
                                            ::testing::Values(false)),
                         variantTestName);
INSTANTIATE_TEST_SUITE_P(Jittered, EmptySpace,
                         ::testing::Combine(::testing::Values(Mode::Iso, Mode::Dvr, Mode::Mip),
                                            ::testing::Values(Gradient::ZuckerHummel),
                                            ::testing::Values(Interp::Nearest, Interp::Linear),
                                            ::testing::Values(true)),
                         variantTestName);

// Packets cover 4x2 or 4x4 pixels (mip at 8 lanes: two 4x2 packets, 4x4): an image whose
// sides are not multiples of them must still get every pixel, and only its own (the per-ray
// image agrees; a stray or missing write would leave the background or overwrite a
// neighbour). 61 rows leave one row of the last 4x2 packets and three of the last 4x4 ones
// outside.
TEST(EmptySpaceExtras, PacketsFillImagesOfOddSizes) {
  for (Mode mode : {Mode::Iso, Mode::Mip}) {
    RenderParams p = essParams(mode, Gradient::Central, Interp::Linear, false);
    p.width = 83;
    p.height = 61;
    using K = RaycasterOptions::Kernel;
    Image perRay = renderEmptySpace(K::Specialised, true, p, kPerRay);
    for (int lanes : {8, 16}) {
      SCOPED_TRACE(testing::Message() << "mode " << int(mode) << ", " << lanes << " lanes");
      Image packets = renderEmptySpace(K::Specialised, true, p, lanes);
      ASSERT_EQ(packets.rgba.size(), size_t(83 * 61 * 4));
      EXPECT_LE(test::maxDiff(packets, perRay), 1);
      // And the ball is there: many pixels differ from the background in the corner.
      int surface = 0;
      for (size_t i = 0; i < packets.rgba.size(); i += 4)
        surface += packets.rgba[i] != packets.rgba[0];
      EXPECT_GT(surface, 100);  // the ball (radius 10 of a 64-voxel box) covers about 130
    }
  }
}

TEST(EmptySpaceExtras, PacketLanesOtherThan8Or16AreRefused) {
  Raycaster rc(test::pocl(), sparseVolume(), VolumeStorage::Buffer);
  RaycasterOptions o;
  o.packetLanes = 12;
  try {
    rc.setOptions(o);
    FAIL() << "12 lanes were accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    EXPECT_NE(std::string(e.what()).find("8, 16"), std::string::npos) << e.what();
  }
}

// mip skips by the window too: a window whose low end is inside the data (values below it
// show black) and whose high end is reached (rays stop once white). Every pixel must stay,
// through the packets' walk-once path and, on the long volume, their in-order loop.
TEST(EmptySpaceExtras, MipSkippingByWindowAndMaximumChangesNoPixel) {
  using K = RaycasterOptions::Kernel;
  for (bool along : {false, true})
    for (Interp interp : {Interp::Linear, Interp::Nearest})
      for (glm::dvec2 window : {glm::dvec2(0.0, 0.0), glm::dvec2(700.0, 450.0)}) {
        SCOPED_TRACE(testing::Message()
                     << "long " << along << " interp " << int(interp) << " window " << window.x);
        RenderParams p = essParams(Mode::Mip, Gradient::Central, interp, false);
        p.windowWidth = window.x;
        p.windowLevel = window.y;
        if (along) p.camera = {90.0, 0.0, 60.0};  // from the left, down the long axis
        const Volume& v = along ? longVolume() : noisyVolume();
        // Skipping on and off: the same kernel must give the same pixels.
        Image plain = renderEmptySpace(K::Specialised, false, p, kPerRay, v);
        EXPECT_EQ(test::maxDiff(plain, renderEmptySpace(K::Specialised, true, p, kPerRay, v)), 0);
        // Other compilations of the same algorithm: float contraction, one level at most.
        for (int lanes : {8, 16}) {
          Image packets = renderEmptySpace(K::Specialised, false, p, lanes, v);
          EXPECT_EQ(test::maxDiff(packets, renderEmptySpace(K::Specialised, true, p, lanes, v)), 0);
          EXPECT_LE(test::maxDiff(plain, packets), 1) << lanes << " lanes";
        }
        EXPECT_LE(test::maxDiff(plain, renderEmptySpace(K::Uber, true, p, kPerRay, v)), 1);
        // Not a blank test: greys, and with the narrow window saturated pixels too.
        int white = 0, grey = 0;
        for (size_t i = 0; i < plain.rgba.size(); i += 4) {
          white += plain.rgba[i] == 255;
          grey += plain.rgba[i] > 0 && plain.rgba[i] < 255;
        }
        EXPECT_GT(grey, 100);
        if (window.x > 0.0) {
          EXPECT_GT(white, 20);
        }
      }
}

TEST(EmptySpaceExtras, ClassifiesOnlyWhenTheRangeOrTableChanges) {
  Raycaster rc(test::pocl(), sparseVolume(), VolumeStorage::Buffer);
  RenderParams p = essParams(Mode::Iso, Gradient::Central, Interp::Linear, false);
  rc.render(p);
  p.camera.azimuthDeg += 40.0;  // the camera moves: nothing to reclassify
  rc.render(p);
  EXPECT_EQ(rc.classifications(), 1);
  p.isoLo = 500.0;
  rc.render(p);
  EXPECT_EQ(rc.classifications(), 2);
  p.mode = Mode::Dvr;
  p.preset = "CT-Bone";
  rc.render(p);
  p.presetShiftHu = 200.0;  // moves the table's opaque part
  rc.render(p);
  EXPECT_EQ(rc.classifications(), 4);
}

// A transfer-function drag reclassifies the grid the raycaster keeps, edit after edit (the
// occupancy folded per stored value, the distances in linear passes): after each edit its frame
// must be the one a raycaster without skipping makes, pixel for pixel (the tolerance of
// SkippingChangesNoPixel: skipping leaps only samples that cannot change a pixel). Tables that
// move by 1 HU and far, narrow spikes in the noise and on the blobs, and a table opaque only at
// the bottom of the data.
TEST(EmptySpaceExtras, TableEditsKeepSkippingExact) {
  auto spike = [](double lo, double hi, double a) {
    return std::vector<ControlPoint>{{lo - 1.0, {1.0, 0.8, 0.6, 0.0}},
                                     {lo, {1.0, 0.8, 0.6, a}},
                                     {hi, {0.9, 0.3, 0.2, a}},
                                     {hi + 1.0, {0.9, 0.3, 0.2, 0.0}}};
  };
  std::vector<RenderParams> edits;
  RenderParams p = essParams(Mode::Dvr, Gradient::Central, Interp::Linear, false);
  for (double shift : {0.0, 1.0, 0.0, -350.0, 250.0}) {
    p.presetShiftHu = shift;
    edits.push_back(p);
  }
  p.presetShiftHu = 0.0;
  for (auto [lo, hi, a] : {std::tuple{100.0, 120.0, 0.3},
                           {101.0, 121.0, 0.3},
                           {900.0, 905.0, 0.8},
                           {-400.0, -380.0, 0.05},
                           {590.0, 600.0, 0.5}}) {
    p.transferFunction = spike(lo, hi, a);
    edits.push_back(p);
  }
  for (int lanes : {kPerRay, 16}) {
    SCOPED_TRACE(testing::Message() << (lanes == kPerRay ? "one ray per work-item" : "16 lanes"));
    Raycaster rc(test::pocl(), noisyVolume(), VolumeStorage::Buffer);
    RaycasterOptions o;
    o.packets = lanes != kPerRay;
    o.packetLanes = lanes == kPerRay ? 0 : lanes;
    rc.setOptions(o);
    int edit = 0, shown = 0;
    for (const RenderParams& e : edits) {
      SCOPED_TRACE(testing::Message() << "edit " << edit);
      Image skipped = rc.render(e);
      EXPECT_EQ(rc.classifications(), ++edit);  // each edit reclassified the kept grid
      Image plain =
          renderEmptySpace(RaycasterOptions::Kernel::Specialised, false, e, lanes, noisyVolume());
      EXPECT_EQ(test::maxDiff(plain, skipped), 0);
      for (size_t i = 0; i < plain.rgba.size(); i += 4) shown += plain.rgba[i] > 20;
    }
    EXPECT_GT(shown, 1000);  // not a blank sequence: the tables show something
  }
}

// The iso block bits are made only for the packets that read them (8 lanes), and a change
// of width reclassifies for the new packets.
TEST(EmptySpaceExtras, IsoBlockBitsOnlyForEightLanePackets) {
  // Packets are the CPU path: a GPU (VOXRAY_TEST_DEVICE=gpu) renders one ray per work-item.
  if (test::pocl().device().isGpu) GTEST_SKIP() << "ray packets run on CPU devices only";
  Raycaster rc(test::pocl(), sparseVolume(), VolumeStorage::Buffer);
  RenderParams p = essParams(Mode::Iso, Gradient::Central, Interp::Linear, false);
  RaycasterOptions o;
  o.packetLanes = 16;
  rc.setOptions(o);
  const Image wide = rc.render(p);
  EXPECT_EQ(rc.classifications(), 1);
  EXPECT_EQ(rc.isoBlockScans(), 0);
  o.packetLanes = 8;
  rc.setOptions(o);
  const Image narrow = rc.render(p);
  EXPECT_EQ(rc.isoBlockScans(), 1);
  p.isoLo = 500.0;
  rc.render(p);
  EXPECT_EQ(rc.isoBlockScans(), 2);
  o.packets = false;  // one ray per work-item reads neither
  rc.setOptions(o);
  rc.render(p);
  EXPECT_EQ(rc.isoBlockScans(), 2);
  // The same surface either way (packets of both widths hit the same first crossing).
  EXPECT_EQ(test::maxDiff(wide, narrow), 0);
}

TEST(EmptySpaceExtras, ClipBoxAndOrthographicToo) {
  RenderParams p = essParams(Mode::Iso, Gradient::Central, Interp::Linear, true);
  p.camera.projection = Projection::Orthographic;
  p.clip.lo = {0.1, 0.45, 0.0};
  p.clip.hi = {0.7, 1.0, 0.9};
  using K = RaycasterOptions::Kernel;
  EXPECT_EQ(test::maxDiff(renderEmptySpace(K::Specialised, false, p),
                          renderEmptySpace(K::Specialised, true, p)),
            0);
}

}  // namespace voxray
