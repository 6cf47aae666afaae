// Stability on degenerate and extreme volumes: tiny and flat shapes, 5000:1 anisotropy,
// constant values, the int16 extremes side by side, and float data with NaN and infinities.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include "reference_sampling.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/reference_renderer.h"
#include "voxray/io/raw_import.h"

namespace voxray {

namespace {

Volume filled(glm::ivec3 dims, glm::dvec3 spacing, auto&& value) {
  Volume v;
  v.dims = dims;
  v.spacingMm = spacing;
  v.voxels.resize(v.voxelCount());
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) v.voxels[v.index(x, y, z)] = int16_t(value(x, y, z));
  return v;
}

RenderParams oblique(Mode m) {
  RenderParams p = test::tinyParams(m);
  p.camera.azimuthDeg = 35.0;
  p.camera.elevationDeg = 20.0;
  return p;
}

}  // namespace

TEST(StabilityVolume, TinyAndFlatVolumes) {
  struct Case {
    glm::ivec3 dims;
    const char* name;
  };
  for (Case c : {Case{{1, 1, 1}, "1x1x1"}, Case{{1, 12, 12}, "1xNxN"}, Case{{12, 12, 1}, "NxNx1"},
                 Case{{2, 2, 2}, "2x2x2"}}) {
    // A corner-to-corner gradient where there is room for one; 1000 HU in a single voxel.
    Volume v = filled(c.dims, glm::dvec3(1.0), [&](int x, int y, int z) {
      return -1000 + 2000 * (x + y + z) / std::max(1, c.dims.x + c.dims.y + c.dims.z - 3);
    });
    if (v.voxelCount() == 1) v.voxels[0] = 1000;
    for (Mode m : test::kAllModes) {
      test::expectStable(v, oblique(m), c.name);
      RenderParams p = test::tinyParams(m);
      p.camera.elevationDeg = 90.0;
      test::expectStable(v, p, std::string(c.name) + " from above");
    }
  }
}

TEST(StabilityVolume, AnisotropyFiveThousandToOne) {
  // 0.01 mm next to 50 mm: the default step (half of 0.01 mm) takes ~80000 samples per
  // ray across the 50 mm axis, and gradients scale by 5000 between axes.
  Volume v = test::ball({8, 8, 8}, 2.5, 1000.0, -1000.0, {0.01, 50.0, 1.0});
  for (Mode m : test::kAllModes) {
    RenderParams p = test::tinyParams(m, 24, 16);
    test::expectStable(v, p, "spacing 0.01 / 50 / 1 mm");
    p.camera.azimuthDeg = 90.0;
    test::expectStable(v, p, "spacing 0.01 / 50 / 1 mm, along x");
  }
}

TEST(StabilityVolume, ConstantVolumeHasZeroGradientEverywhere) {
  Volume v = test::constant({8, 8, 8}, 500);
  for (Mode m : test::kAllModes) {
    RenderParams p = oblique(m);
    p.isoLo = 400.0;  // every ray hits at its first sample, where the gradient is zero
    test::expectStable(v, p, "constant 500 HU");
    p.clip.lo = glm::dvec3(0.2);  // a cap on the clip face, then inside, both flat
    p.camera.distanceMm = 1.0;
    test::expectStable(v, p, "constant 500 HU, eye inside the clip box");
  }
}

namespace {
Volume int16Checkerboard() {
  return filled({8, 8, 8}, glm::dvec3(1.0),
                [](int x, int y, int z) { return (x + y + z) % 2 ? 32767 : -32768; });
}
}  // namespace

TEST(StabilityVolume, Int16ExtremesNextToEachOther) {
  Volume v = int16Checkerboard();
  for (Mode m : test::kAllModes)
    for (Interp interp : {Interp::Linear, Interp::Nearest})
      for (bool shading : {true, false}) {
        RenderParams p = oblique(m);
        p.interp = interp;
        p.shading = shading;
        std::string what = std::string("checkerboard -32768 / 32767 ") + toString(interp);
        if (!shading || m == Mode::Mip) {  // no gradient taken
          test::expectStable(v, p, what);
          continue;
        }
        for (Gradient g : {Gradient::Central, Gradient::Sobel, Gradient::ZuckerHummel}) {
          p.gradient = g;
          test::expectStable(v, p, what + " shaded " + toString(g));
        }
      }
}

TEST(StabilityVolume, CancelledGradientIsExactlyZeroButASmallRealOneIsKept) {
  // The rule both renderers share: a gradient at most 1e-5 times the largest |voxel| the
  // stencil read is 0. The checkerboard's is 0 in exact arithmetic everywhere the stencil
  // stays off the faces; a ramp of 1 unit per voxel riding on 30000 (threshold 0.3) stays.
  Volume board = int16Checkerboard();
  Volume ramp = filled({8, 8, 8}, glm::dvec3(1.0), [](int x, int, int) { return 30000 + x; });
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(1.0, 5.999);  // p +- 1 stays inside 0..7
  for (Gradient g : {Gradient::Central, Gradient::Sobel, Gradient::ZuckerHummel})
    for (Interp interp : {Interp::Linear, Interp::Nearest})
      for (int i = 0; i < 50; ++i) {
        glm::dvec3 p(u(rng), u(rng), u(rng));
        EXPECT_EQ(volumeGradient(board, interp, g, p), glm::dvec3(0.0)) << toString(g);
        glm::dvec3 r = volumeGradient(ramp, interp, g, p);
        EXPECT_NEAR(r.x, 1.0, 1e-9) << toString(g) << " " << toString(interp);
        EXPECT_NEAR(r.y, 0.0, 1e-9);
        EXPECT_NEAR(r.z, 0.0, 1e-9);
      }
}

// Away from the faces the true trilinear gradient of the checkerboard is exactly 0
// (v(p + e) = v(p - e)), but in float the differences of values near +-32767 carry
// cancellation noise of about |v| 2^-23 (~4e-3, up to ~0.03 with the position's rounding).
// With the old absolute threshold (safe_normalize: largest component > 1e-6) the kernel
// normalised that noise into a random normal while the reference (double, noise ~1e-11)
// fell back to the view vector: mean 1.96 levels, max 108 levels apart. Both renderers now
// call a gradient of at most 1e-5 times the largest |voxel| the stencil read zero.
TEST(StabilityVolume, Int16ExtremesShadedTrilinearDvrTreatsCancelledGradientAsZero) {
  test::expectStable(int16Checkerboard(), oblique(Mode::Dvr), "checkerboard, shaded dvr");
}

TEST(StabilityVolume, FloatVolumeWithNaNAndInfinitiesIsEmptyThereWithAWarning) {
  const int n = 8;
  std::vector<float> data(size_t(n) * n * n);
  for (int i = 0; i < n * n * n; ++i) data[size_t(i)] = float(i % n) * 250.0f - 1000.0f;
  data[10] = std::numeric_limits<float>::quiet_NaN();
  data[100] = std::numeric_limits<float>::infinity();
  data[300] = -std::numeric_limits<float>::infinity();
  auto path = std::filesystem::temp_directory_path() / "voxray_stability_nan.f32";
  {
    std::ofstream f(path, std::ios::binary);
    f.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size() * 4));
  }
  RawLayout layout;
  layout.dims = {n, n, n};
  layout.type = SampleType::F32;
  Volume v = importRaw(path.string(), layout);
  std::filesystem::remove(path);
  ASSERT_FALSE(v.warnings.empty());
  EXPECT_NE(v.warnings.front().find("NaN or infinite"), std::string::npos) << v.warnings.front();
  // Non-finite voxels became the lowest value (air): they are empty, not bright.
  EXPECT_DOUBLE_EQ(v.toPhysical(v.voxels[10]), -1000.0);
  EXPECT_DOUBLE_EQ(v.toPhysical(v.voxels[100]), -1000.0);
  for (Mode m : test::kAllModes) test::expectStable(v, oblique(m), "f32 with NaN and +-Inf");
}

}  // namespace voxray
