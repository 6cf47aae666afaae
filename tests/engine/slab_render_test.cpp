// A volume split into z slabs (kernels/reconstruction/slabs.cl) must render exactly as one volume:
// each sample reads the same voxels with the same weights from the slab owning floor(z), z shifted
// by an integer (exact in float). The slab limit is forced low so that a small ball, whose surface
// crosses every slab boundary, is stored in 2 to 4 slabs. Both sides run the one-ray-per-work-item
// kernel (slabs leave the 4x2 packets out).
#include <gtest/gtest.h>

#include <tuple>

#include "multi_device_fixture.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/kernel_variant.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

// 30 slices: 3 slabs own 10 each, 2 own 15, 4 own 8 (the last 6). The ball spans z 4.5 to
// 24.5, so its surface crosses each boundary obliquely.
// Slab limits giving 2, 3 and 4 slabs: stored slices (owned plus aprons) times a slice.
size_t slabBytes(int slabs) {
  const size_t slice = 40 * 36 * sizeof(int16_t);
  return slice * (slabs == 2 ? 17 : slabs == 3 ? 14 : 12);
}

RenderParams slabParams(Mode mode, Gradient g, Interp interp, double elevationDeg) {
  RenderParams p;
  p.width = 64;
  p.height = 48;
  p.mode = mode;
  p.gradient = g;
  p.interp = interp;
  p.isoLo = 0.0;
  p.camera.azimuthDeg = 35.0;
  p.camera.elevationDeg = elevationDeg;
  if (mode == Mode::Dvr) p.preset = "CT-Bone";
  return p;
}

}  // namespace

// mode, gradient, interpolation, empty-space skipping, slabs, storage
using SlabCase = std::tuple<Mode, Gradient, Interp, bool, int, VolumeStorage>;
class Slabs : public ::testing::TestWithParam<SlabCase> {};

TEST_P(Slabs, RenderExactlyAsOneVolume) {
  auto [mode, g, interp, ess, slabs, storage] = GetParam();
  if (storage == VolumeStorage::Image3d && !test::pocl().device().imageSupport)
    GTEST_SKIP() << "no image support";
  Raycaster one(test::pocl(), test::partsBall(), storage);
  Raycaster split(test::pocl(), test::partsBall(), storage);
  RaycasterOptions o;
  o.emptySpaceSkipping = ess;
  o.packets = false;
  one.setOptions(o);
  o.maxSlabBytes = slabBytes(slabs);
  split.setOptions(o);
  ASSERT_EQ(one.slabCount(), 1);
  ASSERT_EQ(split.slabCount(), slabs);
  // Oblique, and from above: rays along z through every boundary (perspective: near the
  // axis) and, orthographic, exactly along it.
  for (double elevation : {25.0, 90.0, -90.0}) {
    RenderParams p = slabParams(mode, g, interp, elevation);
    FrameStats stats;
    Image a = one.render(p);
    Image b = split.render(p, &stats);
    EXPECT_NE(stats.variant.find("-D SLABS=" + std::to_string(slabs)), std::string::npos)
        << stats.variant;
    EXPECT_EQ(test::maxDiff(a, b), 0) << "elevation " << elevation;
  }
}

std::string caseName(const ::testing::TestParamInfo<SlabCase>& info) {
  auto [mode, g, interp, ess, slabs, storage] = info.param;
  return kernelVariantName(slabParams(mode, g, interp, 25.0)) + (ess ? "_ess_" : "_") +
         std::to_string(slabs) + "slabs" + (storage == VolumeStorage::Image3d ? "_image" : "");
}

using M = Mode;
using G = Gradient;
using I = Interp;
using S = VolumeStorage;
// Each kernel build on PoCL takes seconds: every mode, operator and interpolation, with
// ESS, slab count and storage varied alongside rather than crossed.
INSTANTIATE_TEST_SUITE_P(
    Bricks, Slabs,
    ::testing::Values(SlabCase{M::Iso, G::Central, I::Linear, true, 3, S::Buffer},
                      SlabCase{M::Iso, G::Central, I::Nearest, false, 2, S::Buffer},
                      SlabCase{M::Iso, G::Sobel, I::Linear, false, 4, S::Buffer},
                      SlabCase{M::Iso, G::Sobel, I::Nearest, true, 3, S::Buffer},
                      SlabCase{M::Iso, G::ZuckerHummel, I::Linear, true, 2, S::Buffer},
                      SlabCase{M::Iso, G::ZuckerHummel, I::Nearest, false, 4, S::Buffer},
                      SlabCase{M::Dvr, G::Central, I::Linear, false, 3, S::Buffer},
                      SlabCase{M::Dvr, G::ZuckerHummel, I::Nearest, true, 4, S::Buffer},
                      SlabCase{M::Dvr, G::Sobel, I::Linear, true, 2, S::Buffer},
                      SlabCase{M::Mip, G::Central, I::Linear, true, 4, S::Buffer},
                      SlabCase{M::Mip, G::Central, I::Nearest, false, 3, S::Buffer},
                      SlabCase{M::Iso, G::Central, I::Linear, true, 3, S::Image3d},
                      SlabCase{M::Dvr, G::ZuckerHummel, I::Linear, false, 2, S::Image3d}),
    caseName);

TEST(Slabs, OrthographicAlongZ) {
  Raycaster one(test::pocl(), test::partsBall(), VolumeStorage::Buffer);
  Raycaster split(test::pocl(), test::partsBall(), VolumeStorage::Buffer);
  RaycasterOptions o;
  o.packets = false;
  one.setOptions(o);
  o.maxSlabBytes = slabBytes(3);
  split.setOptions(o);
  RenderParams p = slabParams(Mode::Iso, Gradient::ZuckerHummel, Interp::Linear, 90.0);
  p.camera.projection = Projection::Orthographic;
  EXPECT_EQ(test::maxDiff(one.render(p), split.render(p)), 0);
}

TEST(Slabs, SplittingOffAndOnAgainFollowsTheLimit) {
  Raycaster rc(test::pocl(), test::partsBall(), VolumeStorage::Buffer);
  RaycasterOptions o;
  o.maxSlabBytes = slabBytes(4);
  rc.setOptions(o);
  EXPECT_EQ(rc.slabCount(), 4);
  o.maxSlabBytes = 0;
  rc.setOptions(o);
  EXPECT_EQ(rc.slabCount(), 1);
  // Packets (CPUs only) need one volume argument: only unsplit volumes get them.
  if (!test::pocl().device().isGpu)
    EXPECT_NE(rc.variantOptions(slabParams(Mode::Iso, Gradient::Central, Interp::Linear, 25.0))
                  .find("-D PACKET=1"),
              std::string::npos);
}

TEST(Slabs, ALimitBelowFiveSlicesIsAClearDeviceError) {
  Raycaster rc(test::pocl(), test::partsBall(), VolumeStorage::Buffer);
  RaycasterOptions o;
  o.maxSlabBytes = 4 * 40 * 36 * sizeof(int16_t);  // no slab depth leaves room for aprons
  try {
    rc.setOptions(o);
    FAIL() << "no error for an impossible slab limit";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Device);
    std::string m = e.what();
    EXPECT_NE(m.find("40x36x30"), std::string::npos) << m;
    EXPECT_NE(m.find("slab limit"), std::string::npos) << m;
    EXPECT_NE(m.find("crop or downsample"), std::string::npos) << m;
  }
  EXPECT_EQ(rc.slabCount(), 1);  // the volume on the device is unchanged
}

}  // namespace voxray
