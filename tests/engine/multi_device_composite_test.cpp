// The sort-last composite on the first device (MultiDeviceOptions::Composite::Device: the
// other parts' images in half floats, composited band by band by
// kernels/multidev/composite_parts.cl) against the host's composite of the float images, on
// PoCL's CPU sub-devices (2 parts) and contexts on the one CPU (3 parts).
//
// Tolerance: one 8-bit level per channel. Both composite the same samples in the same order;
// the device's other parts are rounded to half floats (relative error at most 2^-11 per
// value), which moves "over"'s sum by at most 2 * 2^-11 * 255 = 0.25 of a level (the colour
// and, through the transmittance, the parts behind); where that moves dvr's opacity across
// earlyTermination (0.999 here) the difference grows by at most 1 - 0.999 = 0.26 of a level.
// Under one level in all, so the rounded bytes differ by at most one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>

#include "frame_bands.h"
#include "multi_device_fixture.h"
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/multi_device.h"

namespace voxray {

namespace {

const Volume& ball() { return test::partsBall(); }
std::vector<ClContext*> contextsOf(int n) { return test::partContexts(n); }

RenderParams compositeFrame(Mode mode, double elevationDeg, bool inside) {
  RenderParams p;
  p.width = 64;
  p.height = 50;  // 3 bands of 17, 17 and 16 rows: the last one shorter
  p.mode = mode;
  p.isoLo = mode == Mode::Iso ? 0.0 : p.isoLo;
  if (mode == Mode::Dvr) p.preset = "CT-Bone";
  p.earlyTermination = 0.999;
  p.camera.azimuthDeg = 35.0;
  p.camera.elevationDeg = elevationDeg;
  if (inside) {  // rays run up and down z from one pixel to the next
    p.camera.distanceMm = 5.0;
    p.camera.fovDeg = 100.0;
  }
  return p;
}

void expectDeviceEqualsHost(Mode mode, int parts) {
  MultiDeviceOptions host, device;
  host.composite = MultiDeviceOptions::Composite::Host;
  device.composite = MultiDeviceOptions::Composite::Device;
  device.bands = 3;
  MultiDeviceRenderer onHost(contextsOf(parts), ball(), host);
  MultiDeviceRenderer onDevice(contextsOf(parts), ball(), device);
  struct View {
    double elevation;
    bool inside;
    const char* name;
  };
  // Along +z, along -z (the slabs' order reversed), oblique and from inside the volume.
  for (View v : {View{90.0, false, "along+z"}, View{-90.0, false, "along-z"},
                 View{25.0, false, "oblique"}, View{60.0, true, "eye-inside"}}) {
    RenderParams p = compositeFrame(mode, v.elevation, v.inside);
    MultiDeviceStats hs, ds;
    Image a = onHost.render(p, &hs);
    Image b = onDevice.render(p, &ds);
    EXPECT_FALSE(hs.deviceComposite);
    EXPECT_TRUE(ds.deviceComposite) << v.name;
    ASSERT_EQ(b.width, 64);
    ASSERT_EQ(b.height, 50);
    ASSERT_EQ(ds.parts.size(), size_t(parts));
    EXPECT_LE(test::maxDiff(a, b), 1)
        << toString(mode) << ", " << v.name << ", " << parts << " parts";
    // Not a blank frame that agrees trivially: the ball shows. (A band left out would fail
    // the comparison: its alpha bytes stay 0, the host's are 255.)
    int lit = 0;
    for (size_t px = 0; px < a.rgba.size(); px += 4) lit += a.rgba[px] > 20;
    EXPECT_GT(lit, int(a.rgba.size() / 4 / 50)) << toString(mode) << ", " << v.name;
  }
}

}  // namespace

TEST(MultiDeviceComposite, DvrOnDeviceEqualsHost) {
  expectDeviceEqualsHost(Mode::Dvr, 2);
  expectDeviceEqualsHost(Mode::Dvr, 3);
}

TEST(MultiDeviceComposite, MipOnDeviceEqualsHost) {
  expectDeviceEqualsHost(Mode::Mip, 2);
  expectDeviceEqualsHost(Mode::Mip, 3);
}

TEST(MultiDeviceComposite, IsoOnDeviceEqualsHost) {
  expectDeviceEqualsHost(Mode::Iso, 2);
  expectDeviceEqualsHost(Mode::Iso, 3);
}

// The parts' images stay the host's floats for renderParts (an MPI rank's, IceT's input)
// after device-composited frames.
TEST(MultiDeviceComposite, PartsStayOnTheHostAfterDeviceFrames) {
  MultiDeviceOptions o;
  o.bands = 2;
  MultiDeviceRenderer r(contextsOf(2), ball(), o);
  RenderParams p = compositeFrame(Mode::Mip, 25.0, false);
  Image composited = r.render(p);
  std::vector<PartImage> parts = r.renderParts(p);
  ASSERT_EQ(parts.size(), 2u);
  // Mip: the frame is the larger of the parts' greys where a ray met the clip box.
  int worst = 0, met = 0;
  for (size_t px = 0; px < size_t(p.width) * size_t(p.height); ++px) {
    const float* a = parts[0].colour + px * 4;
    const float* b = parts[1].colour + px * 4;
    if (a[3] <= 0.0f) continue;
    ++met;
    const int grey = int(std::lround(std::max(a[0], b[0]) * 255.0f));
    worst = std::max(worst, std::abs(grey - int(composited.rgba[px * 4])));
  }
  EXPECT_GT(met, 1000);
  EXPECT_LE(worst, 1);  // half floats: 0.125 of a level, one level after rounding
}

// --balance: every part holds the whole volume and the planes move between frames toward
// equal kernel times; each frame stays the host composite's of fixed ranges within the same
// level (every sample is still taken by exactly one part).
TEST(MultiDeviceComposite, BalancedRangesMoveAndKeepThePixels) {
  MultiDeviceOptions fixed, moving;
  fixed.composite = MultiDeviceOptions::Composite::Host;
  moving.balance = true;
  MultiDeviceRenderer a(contextsOf(2), ball(), fixed);
  MultiDeviceRenderer b(contextsOf(2), ball(), moving);
  const std::vector<PartRange> planned = b.ranges();
  ASSERT_EQ(planned.size(), 2u);
  EXPECT_EQ(planned[0].storedFirst, 0);
  EXPECT_EQ(planned[0].storedEnd, 30);  // the whole volume, on each part
  EXPECT_EQ(planned[1].storedFirst, 0);
  // Seen from above (elevation 80) the upper slabs hide the lower ones for dvr: the parts'
  // costs differ, so the plane moves.
  bool moved = false;
  for (int frameIndex = 0; frameIndex < 4; ++frameIndex) {
    RenderParams p = compositeFrame(Mode::Dvr, 80.0, false);
    p.camera.azimuthDeg += 10.0 * frameIndex;
    MultiDeviceStats stats;
    Image want = a.render(p);
    Image got = b.render(p, &stats);
    EXPECT_LE(test::maxDiff(want, got), 1) << "frame " << frameIndex;
    const std::vector<PartRange> now = b.ranges();
    EXPECT_EQ(now[0].first, 0);
    EXPECT_EQ(now[0].end, now[1].first);  // contiguous
    EXPECT_EQ(now[1].end, 30);
    moved = moved || now[0].end != planned[0].end;
    std::cout << "frame " << frameIndex << ": plane at slice " << now[0].end << ", kernels "
              << stats.parts[0].kernelMs << " and " << stats.parts[1].kernelMs << " ms\n";
  }
  EXPECT_TRUE(moved);
}

TEST(MultiDeviceComposite, BandsCoverTheFrameInWholeWorkGroups) {
  // 4K: 8 bands of 272 rows (34 work-groups of 8), the last 256.
  std::vector<FrameBand> b = frameBands(2160, 0, 8);
  ASSERT_EQ(b.size(), 8u);
  EXPECT_EQ(b[0].rows, 272);
  EXPECT_EQ(b[7].first, 7 * 272);
  EXPECT_EQ(b[7].rows, 2160 - 7 * 272);
  // A small frame: one band.
  b = frameBands(240, 0, 8);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].rows, 240);
  // 50 rows in 3 bands of whole rows.
  b = frameBands(50, 3, 1);
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[1].first, 17);
  EXPECT_EQ(b[2].rows, 16);
}

}  // namespace voxray
