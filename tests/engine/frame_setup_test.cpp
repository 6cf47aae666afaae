// The frame setup's cache key (frame_setup.h, SetupKey): it changes exactly when a field the
// setup's table and thresholds read changes, and the raycaster rebuilds them then.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "frame_setup.h"  // engine-internal
#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/raycaster.h"

namespace voxray {

namespace {

using Change = std::pair<std::string, std::function<void(RenderParams&)>>;

RenderParams base() {
  RenderParams p = test::tinyParams(Mode::Dvr);
  p.preset = "CT-Bone";
  p.windowWidth = 400.0;
  p.windowLevel = 40.0;
  return p;
}

// The costly part two setups made from A and B differ in: table, thresholds or window.
bool tablesDiffer(const FrameSetup& a, const FrameSetup& b) {
  return a.lut.rgba != b.lut.rgba || a.lut.storedMin != b.lut.storedMin ||
         a.lut.scale != b.lut.scale || a.isoLoStored != b.isoLoStored ||
         a.isoHiStored != b.isoHiStored || a.windowLoStored != b.windowLoStored ||
         a.windowInvWidth != b.windowInvWidth || a.referenceStepMm != b.referenceStepMm;
}

}  // namespace

TEST(FrameSetupKey, ChangesWithEveryFieldTheTablesRead) {
  const Volume v = test::ball({12, 12, 12}, 4.0);
  auto noPreset = [](RenderParams& p) { p.preset.clear(); };  // the mode's default table
  auto plainIso = [](RenderParams& p) {                       // the plain surface colour
    p.mode = Mode::Iso;
    p.preset.clear();
  };
  auto same = [](RenderParams&) {};
  struct Case {
    std::string what;
    std::function<void(RenderParams&)> both, change;
  };
  const std::vector<Case> cases = {
      {"mode", noPreset, [](RenderParams& p) { p.mode = Mode::Iso; }},
      {"preset", same, [](RenderParams& p) { p.preset = "CT-Muscle"; }},
      {"preset shift", same, [](RenderParams& p) { p.presetShiftHu = 150.0; }},
      {"tf", same,
       [](RenderParams& p) {
         p.transferFunction = {{0.0, {1, 0, 0, 0.5}}};
       }},
      {"opacity unit", same, [](RenderParams& p) { p.opacityUnitMm = 2.0; }},
      {"surface colour", plainIso,
       [](RenderParams& p) {
         p.surfaceColor = {0.2, 0.4, 0.9};
       }},
      {"iso lo", same, [](RenderParams& p) { p.isoLo = 100.0; }},
      {"iso hi", same, [](RenderParams& p) { p.isoHi = 900.0; }},
      {"window width", same, [](RenderParams& p) { p.windowWidth = 800.0; }},
      {"window level", same, [](RenderParams& p) { p.windowLevel = 300.0; }}};
  for (const Case& c : cases) {
    RenderParams p = base();
    c.both(p);
    RenderParams q = p;
    c.change(q);
    EXPECT_FALSE(setupKeyOf(p) == setupKeyOf(q)) << c.what;
    EXPECT_TRUE(tablesDiffer(makeFrameSetup(v, p), makeFrameSetup(v, q))) << c.what;
  }
}

TEST(FrameSetupKey, KeepsAcrossCameraSizeStepAndWhatOnlyTheKernelReads) {
  const Volume v = test::ball({12, 12, 12}, 4.0);
  const std::vector<Change> changes = {
      {"camera", [](RenderParams& p) { p.camera.azimuthDeg = 40.0; }},
      {"size",
       [](RenderParams& p) {
         p.width = 7;
         p.height = 5;
       }},
      {"step", [](RenderParams& p) { p.stepMm = 1.5; }},
      {"refine", [](RenderParams& p) { p.refine = 9; }},
      {"gradient", [](RenderParams& p) { p.gradient = Gradient::Sobel; }},
      {"interp", [](RenderParams& p) { p.interp = Interp::Nearest; }},
      {"clip", [](RenderParams& p) { p.clip.lo.x = 0.3; }},
      {"light", [](RenderParams& p) { p.light.ambient = 0.6; }},
      {"jitter", [](RenderParams& p) { p.jitter = true; }}};
  const RenderParams p = base();
  const FrameSetup s = makeFrameSetup(v, p);
  for (const auto& [what, change] : changes) {
    RenderParams q = p;
    change(q);
    EXPECT_TRUE(setupKeyOf(p) == setupKeyOf(q)) << what;
    EXPECT_FALSE(tablesDiffer(s, makeFrameSetup(v, q))) << what;
  }
  // The per-frame part still follows the frame: its step and its view.
  RenderParams q = p;
  q.stepMm = 1.5;
  q.camera.azimuthDeg = 40.0;
  FrameSetup t = makeValueSetup(v, setupKeyOf(p));
  placeFrame(t, v, q);
  EXPECT_EQ(t.stepMm, 1.5);
  EXPECT_EQ(t.view.eye, makeFrameSetup(v, q).view.eye);
  EXPECT_NE(t.view.eye, s.view.eye);
}

// The raycaster keeps one setup between frames: a frame after a table change must be the
// frame a fresh raycaster renders, and one after a camera and step change too.
TEST(FrameSetupKey, RaycasterRebuildsTheTablesWhenTheKeyChanges) {
  const Volume v = test::ball({24, 24, 24}, 8.0);
  RenderParams p = base();
  Raycaster cached(test::pocl(), v, VolumeStorage::Buffer);
  cached.render(p);
  for (const auto& change : std::vector<std::function<void(RenderParams&)>>{
           [](RenderParams& q) { q.presetShiftHu = -600.0; },
           [](RenderParams& q) {
             q.camera.azimuthDeg = 70.0;
             q.stepMm = 0.75;
           }}) {
    change(p);
    const Image after = cached.render(p);
    Raycaster fresh(test::pocl(), v, VolumeStorage::Buffer);
    EXPECT_EQ(test::maxDiff(after, fresh.render(p)), 0);
  }
}

}  // namespace voxray
