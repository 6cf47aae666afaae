// The part renderer as an MPI rank uses it (app/mpi, issue 38 part 5): one renderer per part
// with its range given (MultiDeviceOptions::ranges), a volume that holds only that part's
// stored slices (the rest filler, as placeSlab makes it) and the whole volume's value range;
// and visibilityKeys(), the one front-to-back order IceT composites dvr in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>

#include "multi_device_fixture.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/multi_device.h"
#include "voxray/io/error.h"

namespace voxray {
namespace {

// 40x36x30 anisotropic ball (multi_device_test.cpp's): 3 parts own 10 slices each.
// V with every slice outside [r.storedFirst, r.storedEnd) set to FILL.
Volume slabOnly(const Volume& v, const PartRange& r, int16_t fill) {
  Volume out = v;
  const size_t slice = size_t(v.dims.x) * size_t(v.dims.y);
  for (int z = 0; z < v.dims.z; ++z)
    if (z < r.storedFirst || z >= r.storedEnd)
      std::fill_n(out.voxels.begin() + std::ptrdiff_t(size_t(z) * slice), slice, fill);
  return out;
}

RenderParams rankFrame(Mode mode, double elevation, double distance = 0.0) {
  RenderParams p;
  p.width = 64;
  p.height = 48;
  p.mode = mode;
  if (mode == Mode::Dvr) p.preset = "CT-Bone";
  p.isoLo = mode == Mode::Iso ? 0.0 : p.isoLo;
  p.earlyTermination = 0.999;
  p.camera.azimuthDeg = 35.0;
  p.camera.elevationDeg = elevation;
  if (distance > 0.0) {  // the eye inside the volume
    p.camera.distanceMm = distance;
    p.camera.fovDeg = 100.0;
  }
  return p;
}

// Each part rendered alone from its slab equals the same part of the whole volume's split:
// the same samples and stencils, the filler never read (float rounding only: 1e-5).
TEST(MultiDeviceRanks, SlabOnlyPartsEqualTheWholeSplit) {
  const Volume& whole = test::partsBall();
  const std::vector<PartRange> ranges = planParts(whole.dims.z, {1.0, 1.0, 1.0}, 4);
  const ValueRange all = storedRange(whole);
  std::vector<std::unique_ptr<ClContext>> owned = splitDevice(test::testDeviceSelector(), 3);
  std::vector<ClContext*> contexts;
  for (auto& c : owned) contexts.push_back(c.get());
  MultiDeviceRenderer split(contexts, whole);
  for (Mode mode : {Mode::Dvr, Mode::Iso, Mode::Mip}) {
    const RenderParams p = rankFrame(mode, 25.0);
    const std::vector<PartImage> reference = split.renderParts(p);
    ASSERT_EQ(reference.size(), 3u);
    const size_t pixels = size_t(p.width) * size_t(p.height);
    std::vector<std::vector<float>> expected;
    for (const PartImage& r : reference) expected.emplace_back(r.colour, r.colour + pixels * 4);
    for (size_t k = 0; k < 3; ++k) {
      const Volume slab = slabOnly(whole, ranges[k], all.min);
      MultiDeviceOptions o;
      o.ranges = {ranges[k]};
      o.valueRange = all;
      MultiDeviceRenderer rank({contexts[k]}, slab, o);
      const PartImage got = rank.renderParts(p).at(0);
      float worst = 0.0f;
      int seen = 0;
      for (size_t i = 0; i < pixels * 4; ++i) {
        worst = std::max(worst, std::abs(got.colour[i] - expected[k][i]));
        seen += i % 4 == 3 && got.colour[i] > 0.0f;
      }
      EXPECT_LE(worst, 1e-5f) << toString(mode) << ", part " << k + 1;
      EXPECT_GT(seen, 0) << toString(mode) << ", part " << k + 1 << " shows nothing";
    }
  }
}

// Where two parts both have samples on a pixel's ray, the one with the lower visibility key
// comes first along it (dvr's order index): one order for every pixel, also with the eye
// inside the middle part, where rays run up and down z.
TEST(MultiDeviceRanks, VisibilityKeysOrderEveryPixel) {
  std::vector<std::unique_ptr<ClContext>> owned = splitDevice(test::testDeviceSelector(), 3);
  std::vector<ClContext*> contexts;
  for (auto& c : owned) contexts.push_back(c.get());
  MultiDeviceRenderer split(contexts, test::partsBall());
  struct View {
    const char* name;
    double elevation, distance;
  };
  for (View v : {View{"along+z", 90.0, 0.0}, View{"along-z", -90.0, 0.0},
                 View{"oblique", 25.0, 0.0}, View{"eye inside", 60.0, 5.0}}) {
    const RenderParams p = rankFrame(Mode::Dvr, v.elevation, v.distance);
    const std::vector<double> keys = split.visibilityKeys(p);
    const std::vector<PartImage> parts = split.renderParts(p);
    const size_t pixels = size_t(p.width) * size_t(p.height);
    int compared = 0;
    for (size_t a = 0; a < 3; ++a)
      for (size_t b = 0; b < 3; ++b) {
        if (keys[a] >= keys[b]) continue;
        for (size_t i = 0; i < pixels; ++i) {
          const float oa = parts[a].order[i], ob = parts[b].order[i];
          if (oa == FLT_MAX || ob == FLT_MAX) continue;
          ++compared;
          ASSERT_LT(oa, ob) << v.name << ": part " << a + 1 << " (key " << keys[a]
                            << ") behind part " << b + 1 << " (key " << keys[b] << ") at pixel "
                            << i;
        }
      }
    EXPECT_GT(compared, 100) << v.name << ": too few rays cross two parts to tell";
  }
}

TEST(MultiDeviceRanks, GivenRangeOutsideTheVolumeIsRefused) {
  MultiDeviceOptions o;
  o.ranges = {PartRange{20, 40, 16, 40}};
  try {
    MultiDeviceRenderer r({&test::pocl()}, test::partsBall(), o);
    FAIL() << "a range past slice 29 was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the range of slices 20 to 39 (held 16 to 39) does not "
                                         "fit the 30 slices"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace voxray
