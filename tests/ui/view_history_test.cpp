// Issue 18 item 11: undo/redo of camera, clip box, light and window/level; a drag is one
// step; a new study starts a new history.
#include <gtest/gtest.h>

#include "study_state.h"
#include "view_history.h"
#include "voxray/io/phantom.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

void turn(AppModels& m, double azimuth) {
  m.render.update(kCamera, [&](RenderParams& p) { p.camera.azimuthDeg = azimuth; });
}

TEST(ViewHistory, UndoAndRedoWalkBackAndForthThroughEdits) {
  AppModels m;
  ViewHistory h(m);
  EXPECT_FALSE(h.canUndo());
  turn(m, 30.0);
  m.render.update(kClip, [](RenderParams& p) { p.clip.lo.x = 0.5; });
  m.windowLevel.set({1500.0, -600.0});
  m.render.update(kLight, [](RenderParams& p) { p.light.position = {1.0, 2.0, 3.0}; });

  h.undo();  // the light
  EXPECT_EQ(m.render.params().light.position, glm::dvec3(0.5, 0.6, 0.0));
  EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 1500.0);
  h.undo();  // the window
  EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 400.0);
  EXPECT_DOUBLE_EQ(m.windowLevel.value().level, 40.0);
  EXPECT_DOUBLE_EQ(m.render.params().clip.lo.x, 0.5);
  h.undo();  // the clip box
  EXPECT_DOUBLE_EQ(m.render.params().clip.lo.x, 0.0);
  h.undo();  // the camera
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 0.0);
  EXPECT_FALSE(h.canUndo());
  h.undo();  // nothing left: no change
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 0.0);

  h.redo();
  h.redo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 30.0);
  EXPECT_DOUBLE_EQ(m.render.params().clip.lo.x, 0.5);
  EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 400.0);
  EXPECT_TRUE(h.canRedo());
  // A new edit after an undo drops what could have been redone.
  turn(m, 90.0);
  EXPECT_FALSE(h.canRedo());
  h.undo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 30.0);
  EXPECT_DOUBLE_EQ(m.render.params().clip.lo.x, 0.5);
}

TEST(ViewHistory, ADragIsOneStep) {
  AppModels m;
  ViewHistory h(m);
  turn(m, 10.0);
  h.beginGesture();
  for (int i = 1; i <= 50; ++i) turn(m, 10.0 + i);
  h.endGesture();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 60.0);
  h.undo();  // the whole drag at once
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 10.0);
  h.undo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 0.0);
  EXPECT_FALSE(h.canUndo());
  h.redo();
  h.redo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 60.0);
  // A gesture that changes nothing (a click) records nothing.
  h.beginGesture();
  h.endGesture();
  h.undo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 10.0);
}

TEST(ViewHistory, AppearanceAndQualityAreNotRecorded) {
  AppModels m;
  ViewHistory h(m);
  m.render.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Dvr; });
  m.render.setQualityPreset("");
  EXPECT_FALSE(h.canUndo());
}

TEST(ViewHistory, OpeningAStudyStartsANewHistory) {
  AppModels m;
  ViewHistory h(m);
  openStudy(m, std::make_shared<const Volume>(makeHeadPhantom(32)), "first");
  EXPECT_FALSE(h.canUndo());  // the study's defaults are not a step
  turn(m, 45.0);
  EXPECT_TRUE(h.canUndo());
  openStudy(m, std::make_shared<const Volume>(makeHeadPhantom(32)), "second");
  EXPECT_FALSE(h.canUndo());
  EXPECT_FALSE(h.canRedo());
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 0.0);
}

TEST(ViewHistory, KeepsAtMostTheLimit) {
  AppModels m;
  ViewHistory h(m);
  for (size_t i = 1; i <= ViewHistory::kLimit + 20; ++i) turn(m, double(i));
  size_t steps = 0;
  while (h.canUndo()) {
    h.undo();
    ++steps;
  }
  EXPECT_EQ(steps, ViewHistory::kLimit);
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 20.0);
}

}  // namespace
