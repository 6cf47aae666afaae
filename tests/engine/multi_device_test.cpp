// One frame over several OpenCL devices, sort-last (voxray/engine/multi_device.h, issue 38 part
// 4), against the one-device frame. On PoCL the parts are 2 sub-devices of the CPU (one core
// each) or, where it has too few cores (3 and 4 parts on a 2-core machine), that many
// contexts on the one CPU: both paths of splitDevice().
//
// Tolerance: one 8-bit level per channel. Each sample of the one-device ray is taken by
// exactly one part at the same position, so the parts' sums differ from the one-pass sum only
// by float rounding of the composite (a different association of the same products), which
// can move a value across a rounding edge by one level. dvr's early termination adds at most
// 1 - earlyTermination (multi_device.h): the frames here set it to 0.999 (0.26 of a level),
// and EarlyTerminationBound checks the default 0.99 against its bound of 2.55 levels + 1.
// Both sides run the one-ray-per-work-item kernels (the parts do not march packets).
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <tuple>

#include "accuracy_cthead.h"
#include "multi_device_fixture.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/multi_device.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

std::vector<ClContext*> contexts(int n) { return test::partContexts(n); }

enum class View { AlongPlusZ, AlongMinusZ, Oblique, Inside };
const char* name(View v) {
  return v == View::AlongPlusZ    ? "along+z"
         : v == View::AlongMinusZ ? "along-z"
         : v == View::Oblique     ? "oblique"
                                  : "eye-inside";
}

// The volume's k axis (z) points along elevation 90 or -90 here (the ball's direction is the
// identity; CThead's LPI puts k to inferior): one of them looks along +z, the other along -z.
void place(RenderParams& p, View v) {
  p.camera.azimuthDeg = 35.0;
  p.camera.elevationDeg = v == View::AlongPlusZ ? 90.0 : v == View::AlongMinusZ ? -90.0 : 25.0;
  if (v == View::Inside) {
    // The eye inside the volume: rays run up and down z from one pixel to the next, so the
    // order of the parts differs per pixel.
    p.camera.elevationDeg = 60.0;
    p.camera.distanceMm = 5.0;
    p.camera.fovDeg = 100.0;
  }
}

struct SplitCase {
  Mode mode;
  bool ess;
  bool shaded;
};

RenderParams splitFrame(const SplitCase& c, View v, int w, int h) {
  RenderParams p;
  p.width = w;
  p.height = h;
  p.mode = c.mode;
  p.shading = c.shaded;
  p.isoLo = c.mode == Mode::Iso ? 0.0 : p.isoLo;
  if (c.mode == Mode::Dvr) p.preset = "CT-Bone";
  p.earlyTermination = 0.999;
  place(p, v);
  return p;
}

void expectSame(const Volume& vol, const SplitCase& c, int n, int w, int h, int tolerance = 1) {
  Raycaster one(test::pocl(), vol, VolumeStorage::Buffer);
  RaycasterOptions o;
  o.emptySpaceSkipping = c.ess;
  o.packets = false;
  one.setOptions(o);
  MultiDeviceOptions mo;
  mo.emptySpaceSkipping = c.ess;
  MultiDeviceRenderer split(contexts(n), vol, mo);
  ASSERT_EQ(split.partCount(), n);
  int worst = 0;
  for (View v : {View::AlongPlusZ, View::AlongMinusZ, View::Oblique, View::Inside}) {
    RenderParams p = splitFrame(c, v, w, h);
    Image a = one.render(p);
    MultiDeviceStats stats;
    Image b = split.render(p, &stats);
    ASSERT_EQ(stats.parts.size(), size_t(n));
    const int diff = test::maxDiff(a, b);
    EXPECT_LE(diff, tolerance) << name(v) << ", " << n << " parts";
    worst = std::max(worst, diff);
    // Not a blank frame that agrees trivially: the volume shows.
    int lit = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) lit += a.rgba[i] > 20;
    EXPECT_GT(lit, int(a.rgba.size() / 4 / 50)) << name(v);
  }
  std::cout << "largest difference over the views: " << worst << " levels\n";
}

}  // namespace

using Param = std::tuple<int, int>;  // parts, case index
const SplitCase kCases[] = {{Mode::Dvr, true, true},
                            {Mode::Dvr, false, true},
                            {Mode::Mip, true, false},
                            {Mode::Iso, true, true}};
std::string caseName(int i) {
  const SplitCase& c = kCases[i];
  return std::string(c.mode == Mode::Dvr   ? "dvr_shaded"
                     : c.mode == Mode::Mip ? "mip"
                                           : "iso") +
         (c.ess ? "_ess" : "_noess");
}

class MultiDevice : public ::testing::TestWithParam<Param> {};

TEST_P(MultiDevice, BallEqualsOneDevice) {
  auto [n, i] = GetParam();
  expectSame(test::partsBall(), kCases[i], n, 64, 48);
}

TEST_P(MultiDevice, CtheadEqualsOneDevice) {
  const Volume* v = test::cthead();
  if (!v) GTEST_SKIP() << "CThead is not in ../shared/data";
  auto [n, i] = GetParam();
  expectSame(*v, kCases[i], n, 96, 96);
}

INSTANTIATE_TEST_SUITE_P(Parts, MultiDevice,
                         ::testing::Combine(::testing::Values(2, 3, 4),
                                            ::testing::Values(0, 1, 2, 3)),
                         [](const ::testing::TestParamInfo<Param>& info) {
                           return std::to_string(std::get<0>(info.param)) + "parts_" +
                                  caseName(std::get<1>(info.param));
                         });

// Jitter, an orthographic camera and a clip box: the per-pixel offsets are the whole ray's in
// every part.
TEST(MultiDeviceFrame, JitterAndOrthographic) {
  RenderParams p = splitFrame({Mode::Dvr, true, true}, View::Oblique, 64, 48);
  p.jitter = true;
  Raycaster one(test::pocl(), test::partsBall(), VolumeStorage::Buffer);
  RaycasterOptions o;
  o.packets = false;
  one.setOptions(o);
  MultiDeviceRenderer split(contexts(3), test::partsBall());
  EXPECT_LE(test::maxDiff(one.render(p), split.render(p)), 1);
  p.camera.projection = Projection::Orthographic;
  p.camera.elevationDeg = 90.0;  // rays exactly along z
  EXPECT_LE(test::maxDiff(one.render(p), split.render(p)), 1);
  // A clip box whose z faces cut the first and last parts: the rays' entry and exit are the
  // clip box's in every part.
  p.clip.lo = {0.1, 0.0, 0.3};
  p.clip.hi = {1.0, 0.8, 0.7};
  p.camera.elevationDeg = 40.0;
  EXPECT_LE(test::maxDiff(one.render(p), split.render(p)), 1);
  p.mode = Mode::Iso;
  p.isoLo = 0.0;
  EXPECT_LE(test::maxDiff(one.render(p), split.render(p)), 1);
}

// The storage GPUs use (image3d_t), on PoCL: the part reads its slices through the same
// voxel_at as one device's image.
TEST(MultiDeviceFrame, ImageStorage) {
  if (!test::pocl().device().imageSupport) GTEST_SKIP() << "no image support";
  Raycaster one(test::pocl(), test::partsBall(), VolumeStorage::Image3d);
  RaycasterOptions o;
  o.packets = false;
  one.setOptions(o);
  MultiDeviceOptions mo;
  mo.storage = VolumeStorage::Image3d;
  MultiDeviceRenderer split(contexts(2), test::partsBall(), mo);
  for (SplitCase c : {SplitCase{Mode::Dvr, true, true}, SplitCase{Mode::Iso, true, true},
                      SplitCase{Mode::Mip, true, false}})
    for (View v : {View::AlongMinusZ, View::Oblique}) {
      RenderParams p = splitFrame(c, v, 64, 48);
      EXPECT_LE(test::maxDiff(one.render(p), split.render(p)), 1) << name(v);
    }
}

// A drag frame's coarse step, 2 voxels along z (the ball's z spacing is 1.3 mm): the samples
// a part takes across its plane (dvr's first and last segments, iso's refinement from the
// sample before) still lie within the 4-slice apron.
TEST(MultiDeviceFrame, CoarseStepWithinApron) {
  Raycaster one(test::pocl(), test::partsBall(), VolumeStorage::Buffer);
  RaycasterOptions o;
  o.packets = false;
  one.setOptions(o);
  MultiDeviceRenderer split(contexts(3), test::partsBall());
  for (SplitCase c : {SplitCase{Mode::Dvr, true, true}, SplitCase{Mode::Iso, true, true}})
    for (View v : {View::AlongPlusZ, View::Oblique}) {
      RenderParams p = splitFrame(c, v, 64, 48);
      p.stepMm = 2.6;
      p.jitter = true;
      EXPECT_LE(test::maxDiff(one.render(p), split.render(p)), 1) << name(v);
    }
}

// A step longer than the apron holds (3.1 slices; the apron of 4 holds 2) is refused, not
// rendered with reads clamped at the stored edge (136 levels off with an apron of 2 in the
// case above).
TEST(MultiDeviceFrame, StepBeyondApronIsRefused) {
  MultiDeviceRenderer split(contexts(2), test::partsBall());
  RenderParams p = splitFrame({Mode::Iso, true, true}, View::Oblique, 16, 16);
  p.stepMm = 4.0;
  try {
    split.render(p);
    FAIL() << "a step beyond the apron was rendered";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("finer --step"), std::string::npos) << e.what();
  }
  p.stepMm = 2.6;  // 2 slices: renders
  EXPECT_NO_THROW(split.render(p));
}

// The default early termination (0.99): a part behind a ray's stopping point adds at most
// 1 - 0.99 of a colour (2.55 levels), plus a level of rounding.
TEST(MultiDeviceFrame, EarlyTerminationBound) {
  const Volume* v = test::cthead();
  if (!v) GTEST_SKIP() << "CThead is not in ../shared/data";
  RenderParams p = test::ctheadDvr(96, 96);
  p.camera.elevationDeg = 90.0;
  Raycaster one(test::pocl(), *v, VolumeStorage::Buffer);
  RaycasterOptions o;
  o.packets = false;
  one.setOptions(o);
  MultiDeviceRenderer split(contexts(2), *v);
  const int diff = test::maxDiff(one.render(p), split.render(p));
  EXPECT_LE(diff, 4);
  std::cout << "largest difference at early termination 0.99: " << diff << " levels\n";
}

// A CPU under PoCL splits into equal sub-devices (clCreateSubDevices); more parts than cores
// fall back to contexts sharing the one device (3 and 4 parts above on a 2-core machine).
TEST(MultiDeviceFrame, CpuSplitsIntoSubDevices) {
  const DeviceInfo& whole = test::pocl().device();
  if (whole.isGpu || whole.computeUnits < 2) GTEST_SKIP() << "not a CPU of 2 or more cores";
  std::vector<ClContext*> c = contexts(2);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NE(c[0]->device().name.find("(sub-device 1 of 2)"), std::string::npos)
      << c[0]->device().name;
  EXPECT_EQ(c[0]->device().computeUnits, whole.computeUnits / 2);
  EXPECT_EQ(c[1]->device().computeUnits, whole.computeUnits / 2);
}

TEST(MultiDeviceFrame, DeviceOverBudgetSaysWhichAndWhat) {
  MultiDeviceOptions o;
  o.budgetBytes = 40 * 36 * 2 * 5;  // 5 slices; each part needs 15 + its apron
  try {
    MultiDeviceRenderer split(contexts(2), test::partsBall(), o);
    FAIL() << "a part over the budget was accepted";
  } catch (const Error& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("device 1 of 2"), std::string::npos) << m;
    EXPECT_NE(m.find("slices 0 to 18"), std::string::npos) << m;  // 15 owned + apron 4
    EXPECT_NE(m.find("budget"), std::string::npos) << m;
    EXPECT_NE(m.find("--split"), std::string::npos) << m;
  }
}

TEST(MultiDeviceFrame, OtherLightingIsRefused) {
  MultiDeviceRenderer split(contexts(2), test::partsBall());
  RenderParams p = splitFrame({Mode::Dvr, true, true}, View::Oblique, 16, 16);
  p.lighting = Lighting::Shadows;
  EXPECT_THROW(split.render(p), Error);
}

TEST(PartPlan, ContiguousProportionalWithAprons) {
  auto r = planParts(30, {1.0, 1.0}, 4);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].first, 0);
  EXPECT_EQ(r[0].end, 15);
  EXPECT_EQ(r[1].first, 15);
  EXPECT_EQ(r[1].end, 30);
  EXPECT_EQ(r[0].storedFirst, 0);
  EXPECT_EQ(r[0].storedEnd, 19);
  EXPECT_EQ(r[1].storedFirst, 11);
  EXPECT_EQ(r[1].storedEnd, 30);
  // By memory: a device with 3x the memory owns 3x the slices.
  auto m = planParts(100, {3.0, 1.0}, 2);
  EXPECT_EQ(m[0].end, 75);
  EXPECT_EQ(m[1].end, 100);
  // More devices than slices is refused; tiny shares still get a slice.
  EXPECT_THROW(planParts(2, {1.0, 1.0, 1.0}, 2), Error);
  auto t = planParts(5, {1000.0, 1.0, 1.0}, 2);
  EXPECT_EQ(t[1].end - t[1].first, 1);
  EXPECT_EQ(t[2].end - t[2].first, 1);
  EXPECT_EQ(t[2].end, 5);
}

}  // namespace voxray
