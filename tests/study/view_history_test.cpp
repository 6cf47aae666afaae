// Issue 18 item 11: undo/redo of camera, clip box, light and window/level; a drag is one
// step; a new study starts a new history. Issue 14: MPR turns and slabs are steps too.
#include <gtest/gtest.h>

#include "study_state.h"
#include "view_history.h"
#include "voxray/io/phantom.h"

using namespace voxray;

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

// Issue 41 item 10: undoing a window change gave the value back but not where it came from.
TEST(ViewHistory, UndoingAWindowChangeBringsBackItsSource) {
  AppModels m;
  m.windowLevel.reset({80.0, 40.0}, "DICOM window 1");
  ViewHistory h(m);
  m.windowLevel.set({1500.0, -600.0});  // the user's: no source
  EXPECT_EQ(m.windowLevel.source(), "");
  h.undo();
  EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 80.0);
  EXPECT_DOUBLE_EQ(m.windowLevel.value().level, 40.0);
  EXPECT_EQ(m.windowLevel.source(), "DICOM window 1");
  EXPECT_EQ(formatWindowLevel(m.windowLevel.value(), m.windowLevel.source()),
            "W 80  L 40\nDICOM window 1");
  h.redo();
  EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 1500.0);
  EXPECT_EQ(m.windowLevel.source(), "");
  h.undo();
  EXPECT_EQ(m.windowLevel.source(), "DICOM window 1");
  EXPECT_FALSE(h.canUndo());
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

// The three views' plane normals (LPS), as the slice views show them.
std::array<glm::dvec3, 3> normals(const CrosshairModel& c) {
  std::array<glm::dvec3, 3> n;
  for (int o = 0; o < 3; ++o)
    n[size_t(o)] = c.frame(sliceAxes(c.direction(), Orientation(o))).normal;
  return n;
}

TEST(ViewHistory, TurnsAndSlabsAreStepsAndUndoRestoresThePlanesExactly) {
  AppModels m;
  // Anisotropic voxels and a tilted direction: the planes turn in mm, not in voxels.
  const glm::dmat3 tilt =
      glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0.96, 0.28), glm::dvec3(0, -0.28, 0.96));
  m.crosshair.setGeometry({64, 64, 40}, {0.7, 0.7, 2.5}, tilt);
  ViewHistory h(m);
  const auto acquisition = normals(m.crosshair);
  const SliceAxes axial = sliceAxes(tilt, Orientation::Axial);
  const SliceAxes coronal = sliceAxes(tilt, Orientation::Coronal);
  // A handle drag: 40 mouse moves, one step.
  h.beginGesture();
  for (int i = 0; i < 40; ++i) m.crosshair.rotateInView(axial, 0.01);
  h.endGesture();
  const auto afterFirst = normals(m.crosshair);
  EXPECT_NE(afterFirst[1], acquisition[1]);  // coronal and sagittal turned, axial kept
  EXPECT_EQ(afterFirst[0], acquisition[0]);
  h.beginGesture();
  for (int i = 0; i < 25; ++i) m.crosshair.rotateInView(coronal, -0.02);
  h.endGesture();
  const auto afterSecond = normals(m.crosshair);
  m.crosshair.setSlab(Orientation::Sagittal, {12.0, SlabMode::MinIp});
  // Scrolling through the slices is reading, not a step.
  m.crosshair.scrollView(axial, 3);
  const glm::dvec3 centre = m.crosshair.centre();

  h.undo();  // the slab
  EXPECT_EQ(m.crosshair.slab(Orientation::Sagittal).thicknessMm, 0.0);
  EXPECT_EQ(normals(m.crosshair), afterSecond);
  h.undo();  // the second drag, whole
  EXPECT_EQ(normals(m.crosshair), afterFirst);
  EXPECT_TRUE(m.crosshair.rotated());
  EXPECT_EQ(m.crosshair.centre(), centre);  // the planes turn back about the crosshair
  h.undo();                                 // the first drag, whole: the acquisition planes
  EXPECT_EQ(normals(m.crosshair), acquisition);
  EXPECT_FALSE(m.crosshair.rotated());
  EXPECT_FALSE(h.canUndo());

  h.redo();
  h.redo();
  EXPECT_EQ(normals(m.crosshair), afterSecond);
  h.redo();
  EXPECT_EQ(m.crosshair.slab(Orientation::Sagittal).thicknessMm, 12.0);
  EXPECT_EQ(m.crosshair.slab(Orientation::Sagittal).mode, SlabMode::MinIp);
  // Reset planes is one step back to the turned planes.
  m.crosshair.resetRotation();
  EXPECT_EQ(normals(m.crosshair), acquisition);
  h.undo();
  EXPECT_EQ(normals(m.crosshair), afterSecond);
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
