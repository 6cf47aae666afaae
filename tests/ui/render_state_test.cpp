#include <gtest/gtest.h>

#include "camera_control.h"
#include "light_gizmo.h"
#include "recent_files.h"
#include "render_state_model.h"
#include "voxray/io/phantom.h"

using namespace voxray;
using namespace voxray::ui;

TEST(RenderState, InteractiveFramesAreCheaperThanFullOnes) {
  RenderParams base;
  Quality q;
  RenderParams full = planFrame(base, q, {800, 600}, false, 1.0);
  RenderParams fast = planFrame(base, q, {800, 600}, true, 1.0);
  EXPECT_EQ(full.width, 800);
  EXPECT_EQ(full.height, 600);
  EXPECT_DOUBLE_EQ(full.stepMm, 0.5);  // the engine's default: half the smallest spacing
  EXPECT_EQ(fast.width, 400);
  EXPECT_EQ(fast.height, 300);
  EXPECT_DOUBLE_EQ(fast.stepMm, 1.0);
  q.resolution = {512, 384};
  q.stepScale = 0.5;
  RenderParams fixed = planFrame(base, q, {800, 600}, false, 2.0);
  EXPECT_EQ(fixed.width, 512);
  EXPECT_DOUBLE_EQ(fixed.stepMm, 0.5);
}

TEST(RenderState, NotifiesWithTheChangeAndRoundTripsAsText) {
  RenderStateModel m;
  unsigned seen = 0;
  m.changed.connect([&](unsigned what) { seen |= what; });
  m.update(kClip, [](RenderParams& p) { p.clip.hi.x = 0.5; });
  EXPECT_EQ(seen, unsigned(kClip));
  m.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Mip; });
  Quality q;
  q.resolution = {640, 480};
  q.stepScale = 2.0;
  m.setQuality(q);
  RenderStateModel copy;
  copy.fromText(m.toText());
  EXPECT_EQ(copy.params().mode, Mode::Mip);
  EXPECT_DOUBLE_EQ(copy.params().clip.hi.x, 0.5);
  EXPECT_EQ(copy.quality().resolution, glm::ivec2(640, 480));
  EXPECT_DOUBLE_EQ(copy.quality().stepScale, 2.0);
  copy.fromText("mode=banana\nnot a line\nzoom=2\n");  // bad lines are skipped
  EXPECT_EQ(copy.params().mode, Mode::Mip);
  EXPECT_DOUBLE_EQ(copy.params().camera.zoom, 2.0);
}

TEST(CameraControl, StandardViewsAndDragDirections) {
  CameraParams c;
  setStandardView(c, StandardView::Left);
  EXPECT_DOUBLE_EQ(c.azimuthDeg, 90.0);
  setStandardView(c, StandardView::Superior);
  EXPECT_DOUBLE_EQ(c.elevationDeg, 90.0);
  resetCamera(c);
  orbit(c, 10, 0, 1.0);  // dragging right: the camera goes left (azimuth down)
  EXPECT_DOUBLE_EQ(c.azimuthDeg, -10.0);
  orbit(c, 0, 500, 1.0);
  EXPECT_DOUBLE_EQ(c.elevationDeg, 90.0);  // stops at the pole
  zoomBy(c, 1000);
  EXPECT_DOUBLE_EQ(c.zoom, 20.0);
  panBy(c, 10, 0, 2.0);  // dragging right moves the look-at point left
  EXPECT_DOUBLE_EQ(c.panMm.x, -20.0);
}

TEST(LightGizmo, DragPutsTheLightUnderTheMouseInBothFrames) {
  Volume v = makeHeadPhantom(32);
  for (bool follow : {true, false}) {
    RenderParams p;
    p.light.followCamera = follow;
    ViewProjection view = makeViewProjection(v, p, {400, 300});
    auto centre = view.project(glm::dvec3(0.0));
    ASSERT_TRUE(centre.has_value());
    glm::dvec2 mouse = *centre + glm::dvec2(-60, -30);  // up and to the left of the centre
    p.light = lightFromScreen(v, p, view, mouse);
    EXPECT_EQ(p.light.followCamera, follow);
    glm::dvec3 w = lightWorld(v, p);
    EXPECT_LT(w.x, 0.0) << "screen left in the anterior view is the patient's right";
    EXPECT_GT(w.z, 0.0) << "screen up is superior";
    EXPECT_LT(w.y, 0.0) << "the light is in front of the volume, towards the viewer";
    auto handle = view.project(lightHandleWorld(v, p));
    ASSERT_TRUE(handle.has_value());
    EXPECT_NEAR(handle->x, mouse.x, 8.0);
    EXPECT_NEAR(handle->y, mouse.y, 8.0);
    LightParams switched = withFollowCamera(v, p, !follow);
    RenderParams q = p;
    q.light = switched;
    q.light.followCamera = !follow;
    EXPECT_NEAR(glm::distance(lightWorld(v, q), w), 0.0, 1e-6);
  }
}

TEST(RecentFiles, MostRecentFirstWithoutDuplicates) {
  std::vector<std::string> l;
  for (int i = 0; i < 10; ++i) l = pushRecent(l, "f" + std::to_string(i));
  EXPECT_EQ(l.size(), kMaxRecentFiles);
  EXPECT_EQ(l.front(), "f9");
  l = pushRecent(l, "f5");
  EXPECT_EQ(l.front(), "f5");
  EXPECT_EQ(std::count(l.begin(), l.end(), "f5"), 1);
}
