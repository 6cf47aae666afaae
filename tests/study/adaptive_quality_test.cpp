// The drag frame-rate controller on synthetic timings: frame time proportional to the
// pixels and samples a frame takes, as the raycaster's is.
#include <random>

#include <gtest/gtest.h>

#include "adaptive_quality.h"
#include "render_state_model.h"
#include "study_state.h"

namespace voxray {
namespace {

constexpr double kViewPixels = 1530.0 * 1040.0;

// Milliseconds for one frame at S on a machine taking MS_PER_MPIXEL per megapixel at the
// preset's 2-voxel step.
double frameMs(const DragSetting& s, double msPerMpixel) {
  return msPerMpixel * kViewPixels * s.scale * s.scale / 1e6 * (2.0 / s.stepVoxels);
}

double fpsAt(const DragSetting& s, double msPerMpixel) { return 1000.0 / frameMs(s, msPerMpixel); }

// The reported case: 3.8-5 fps at half size means about 500 ms per megapixel on 2 cores.
TEST(AdaptiveQuality, SlowMachineConvergesToTargetWithin10Percent) {
  AdaptiveQuality a(20.0, {0.5, 2.0});
  for (int i = 0; i < 60; ++i) a.record(frameMs(a.setting(), 500.0), a.setting());
  EXPECT_NEAR(fpsAt(a.setting(), 500.0), 20.0, 2.0);
  EXPECT_LT(a.setting().scale, 0.5);
  EXPECT_GE(a.setting().scale, 0.25);
  EXPECT_LE(a.changes(), 2);  // one decision is enough when the model holds
}

TEST(AdaptiveQuality, FastMachineGrowsTheImageUpToFullSize) {
  AdaptiveQuality a(20.0, {0.5, 2.0});
  for (int i = 0; i < 60; ++i) a.record(frameMs(a.setting(), 5.0), a.setting());
  EXPECT_DOUBLE_EQ(a.setting().scale, 1.0);  // clamped: faster than needed even at full size
  EXPECT_DOUBLE_EQ(a.setting().stepVoxels, 2.0);
}

TEST(AdaptiveQuality, VerySlowMachineCoarsensTheStepOnceAtTheSmallestScale) {
  AdaptiveQuality a(20.0, {0.5, 2.0});
  for (int i = 0; i < 60; ++i) a.record(frameMs(a.setting(), 800.0), a.setting());
  EXPECT_DOUBLE_EQ(a.setting().scale, 0.25);
  EXPECT_GT(a.setting().stepVoxels, 2.0);
  EXPECT_LE(a.setting().stepVoxels, 4.0);
  EXPECT_NEAR(fpsAt(a.setting(), 800.0), 20.0, 2.0);
}

TEST(AdaptiveQuality, HoldsSteadyUnderNoise) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    for (double msPerMpixel : {500.0, 300.0, 100.0}) {
      AdaptiveQuality a(20.0, {0.5, 2.0});
      std::mt19937 rng(seed);
      std::uniform_real_distribution<double> noise(0.85, 1.15);  // +-15 % per frame
      auto frame = [&] { a.record(frameMs(a.setting(), msPerMpixel) * noise(rng), a.setting()); };
      for (int i = 0; i < 60; ++i) frame();
      const int settled = a.changes();
      const DragSetting s = a.setting();
      EXPECT_NEAR(fpsAt(s, msPerMpixel), 20.0, 2.0) << seed << " " << msPerMpixel;
      for (int i = 0; i < 600; ++i) frame();
      EXPECT_EQ(a.changes(), settled) << seed << " " << msPerMpixel;  // no oscillation
      EXPECT_DOUBLE_EQ(a.setting().scale, s.scale);
    }
  }
}

TEST(AdaptiveQuality, FollowsATargetChangeAndIgnoresFramesOfAnOlderSetting) {
  AdaptiveQuality a(20.0, {0.5, 2.0});
  for (int i = 0; i < 60; ++i) a.record(frameMs(a.setting(), 500.0), a.setting());
  const DragSetting at20 = a.setting();
  // Late frames of the start setting (in flight when it changed) do not count.
  for (int i = 0; i < 60; ++i) a.record(1.0, {0.5, 2.0});
  EXPECT_DOUBLE_EQ(a.setting().scale, at20.scale);
  a.setTargetFps(10.0);
  for (int i = 0; i < 60; ++i) a.record(frameMs(a.setting(), 500.0), a.setting());
  EXPECT_NEAR(fpsAt(a.setting(), 500.0), 10.0, 1.0);
  EXPECT_GT(a.setting().scale, at20.scale);
}

TEST(AdaptiveQuality, StartsFromTheDragPresetAndPlansDragFramesWithItsSetting) {
  const DragSetting preset = dragPresetSetting();
  EXPECT_DOUBLE_EQ(preset.scale, 0.5);  // resources/quality/interactive.json
  EXPECT_DOUBLE_EQ(preset.stepVoxels, 2.0);
  RenderParams base;
  Quality q;
  const DragSetting drag{0.25, 3.0};
  RenderParams p = planFrame(base, q, {1530, 1040}, true, 0.5, &drag);
  EXPECT_EQ(p.width, 383);
  EXPECT_EQ(p.height, 260);
  EXPECT_DOUBLE_EQ(p.stepMm, 1.5);
  RenderParams sharp = planFrame(base, q, {1530, 1040}, false, 0.5, &drag);
  EXPECT_EQ(sharp.width, 1530);  // the setting is for drag frames only
}

// The scheduler (and bench --drag) read each drag frame's setting back from its size and
// step; a read-back outside record's 2 % match would make the controller ignore every frame.
TEST(AdaptiveQuality, DragFramesReadBackAsTheSettingTheyWerePlannedWith) {
  RenderParams base;
  Quality q;
  for (const glm::ivec2 view :
       {glm::ivec2{1024, 768}, glm::ivec2{1530, 1040}, glm::ivec2{256, 256}})
    for (const double scale : {0.25, 0.3, 0.337, 0.5, 0.71, 1.0})
      for (const double step : {2.0, 2.5, 4.0}) {
        const DragSetting drag{scale, step};
        const RenderParams p = planFrame(base, q, view, true, 0.7, &drag);
        const DragSetting back = dragSettingOf(p, view.x, 0.7);
        EXPECT_NEAR(back.scale, scale, 0.02 * scale) << view.x << " " << scale;
        EXPECT_NEAR(back.stepVoxels, step, 1e-9) << step;
        AdaptiveQuality a(20.0, drag);
        for (int i = 0; i < 12; ++i) a.record(500.0, back);  // 10x too slow: counted, changes
        EXPECT_EQ(a.changes(), 1) << view.x << " " << scale << " " << step;
      }
}

TEST(AdaptiveQuality, TargetFrameRateIsAPreferenceDefaulting20) {
  RenderStateModel m;
  EXPECT_DOUBLE_EQ(m.quality().dragFps, 20.0);
  Quality q = m.quality();
  q.dragFps = 30.0;
  m.setQuality(q);
  RenderStateModel next;
  applyPreferences(next, preferencesText(m));
  EXPECT_DOUBLE_EQ(next.quality().dragFps, 30.0);
  next.fromText("ui-drag-fps=0\n");  // clamped to the spin box's range
  EXPECT_DOUBLE_EQ(next.quality().dragFps, kDragFpsMin);
  next.fromText("ui-drag-fps=nan\n");
  EXPECT_DOUBLE_EQ(next.quality().dragFps, kDragFpsMin);
  next.fromText("ui-drag-fps=1000\n");
  EXPECT_DOUBLE_EQ(next.quality().dragFps, kDragFpsMax);
}

}  // namespace
}  // namespace voxray
