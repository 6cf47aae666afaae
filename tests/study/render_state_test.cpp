#include <gtest/gtest.h>

#include "camera_control.h"
#include "light_gizmo.h"
#include "quality_choice.h"
#include "recent_files.h"
#include "render_controls.h"
#include "render_state_model.h"
#include "study_state.h"
#include "voxray/engine/quality.h"
#include "voxray/io/error.h"
#include "voxray/io/phantom.h"

using namespace voxray;

TEST(RenderState, DragFramesUseTheInteractivePresetAndIdleFramesTheChosenOne) {
  const QualityPreset& drag = findQualityPreset("interactive");
  const QualityPreset& ref = findQualityPreset("reference");
  RenderStateModel m;
  m.setQualityPreset("balanced");
  m.update(kAppearance, [](RenderParams& p) {
    p.gradient = Gradient::Sobel;  // the user's choices, unlike every preset's
    p.interp = Interp::Nearest;
  });
  m.setQualityPreset("reference");
  EXPECT_EQ(m.params().gradient, ref.gradient);  // picking a preset takes its operator
  EXPECT_EQ(m.params().interp, ref.interp);
  const double h = 0.8;  // smallest voxel spacing, mm

  RenderParams idle = planFrame(m.params(), m.quality(), {800, 600}, false, h);
  EXPECT_EQ(idle.width, int(800 * ref.resolutionScale + 0.5));
  EXPECT_EQ(idle.height, int(600 * ref.resolutionScale + 0.5));
  EXPECT_DOUBLE_EQ(idle.stepMm, ref.stepVoxels * h);
  EXPECT_EQ(idle.refine, ref.refine);
  EXPECT_EQ(idle.jitter, ref.jitter);
  EXPECT_EQ(idle.gradient, ref.gradient);
  EXPECT_EQ(idle.interp, ref.interp);
  EXPECT_EQ(idle.refine, 8);  // reference.json, so a preset edit shows up here
  EXPECT_DOUBLE_EQ(idle.stepMm, 0.25 * h);

  // Dragging: step, size, refinement and jitter from the interactive preset, whatever was
  // chosen or set; interpolation and gradient stay the user's (the look does not jump).
  m.update(kAppearance, [](RenderParams& p) { p.gradient = Gradient::Central; });
  for (const char* chosen : {"reference", "balanced", ""}) {
    Quality q = m.quality();
    q.preset = chosen;
    m.setQuality(q);
    RenderParams fast = planFrame(m.params(), m.quality(), {800, 600}, true, h);
    EXPECT_EQ(fast.width, int(800 * drag.resolutionScale + 0.5)) << chosen;
    EXPECT_EQ(fast.height, int(600 * drag.resolutionScale + 0.5));
    EXPECT_DOUBLE_EQ(fast.stepMm, drag.stepVoxels * h);
    EXPECT_EQ(fast.interp, m.params().interp);
    EXPECT_EQ(fast.gradient, Gradient::Central);
    EXPECT_EQ(fast.refine, drag.refine);
    EXPECT_EQ(fast.jitter, drag.jitter);
  }
  // interactive.json: half resolution, 2-voxel steps.
  EXPECT_EQ(planFrame(m.params(), m.quality(), {800, 600}, true, h).width, 400);
  EXPECT_DOUBLE_EQ(planFrame(m.params(), m.quality(), {800, 600}, true, h).stepMm, 2.0 * h);

  // The chosen preset's step and refinement with the user's later gradient choice.
  m.setQualityPreset("balanced");
  m.update(kAppearance, [](RenderParams& p) { p.gradient = Gradient::Sobel; });
  RenderParams balanced = planFrame(m.params(), m.quality(), {800, 600}, false, h);
  EXPECT_DOUBLE_EQ(balanced.stepMm, findQualityPreset("balanced").stepVoxels * h);
  EXPECT_EQ(balanced.refine, findQualityPreset("balanced").refine);
  EXPECT_EQ(balanced.gradient, Gradient::Sobel);

  // Custom: the parameters as set (the engine's default step: half the smallest spacing).
  m.setQualityPreset("");
  m.update(kAppearance, [](RenderParams& p) { p.refine = 3; });
  RenderParams custom = planFrame(m.params(), m.quality(), {800, 600}, false, h);
  EXPECT_DOUBLE_EQ(custom.stepMm, 0.5 * h);
  EXPECT_EQ(custom.refine, 3);
  EXPECT_EQ(custom.width, 800);
  Quality fixed = m.quality();
  fixed.resolution = {512, 384};
  m.setQuality(fixed);
  EXPECT_EQ(planFrame(m.params(), m.quality(), {800, 600}, false, h).width, 512);
  EXPECT_EQ(planFrame(m.params(), m.quality(), {800, 600}, true, h).width, 256);

  fixed.preset = "ultra";
  EXPECT_THROW(m.setQuality(fixed), Error);
  EXPECT_THROW(m.setQualityPreset("ultra"), Error);
  EXPECT_EQ(m.quality().preset, "");  // unchanged
}

TEST(RenderState, QualityChoicesShowEachPresetsMeasuredErrorAndSpeed) {
  auto choices = qualityChoices();
  ASSERT_EQ(choices.size(), 4u);
  EXPECT_EQ(choices[0].label, "Interactive");
  EXPECT_EQ(choices[1].label, "Balanced");
  EXPECT_EQ(choices[2].label, "Reference");
  EXPECT_EQ(choices[3].label, "Custom");
  EXPECT_EQ(choices[3].preset, "");
  // balanced.json: psnr_db 41.83, speedup_vs_reference 6.3, ms_per_frame 41.7
  EXPECT_EQ(choices[1].measured,
            "41.8 dB PSNR \u00b7 6.3\u00d7 Reference's speed, measured on PoCL pthread (Xeon, 2 "
            "shared cores), CThead dvr CT-Bone 160x120, azimuth 30");
  EXPECT_NE(choices[1].tooltip.find("41.83 dB PSNR"), std::string::npos) << choices[1].tooltip;
  EXPECT_NE(choices[1].tooltip.find("41.7 ms per frame"), std::string::npos);
  EXPECT_NE(choices[0].tooltip.find("26.2\u00d7"), std::string::npos) << choices[0].tooltip;
  EXPECT_EQ(resolutionLabel({0, 0}), "Window size");
  EXPECT_EQ(resolutionLabel({160, 120}), "160 \u00d7 120");
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
  q.preset = "reference";
  m.setQuality(q);
  RenderStateModel copy;
  copy.fromText(m.toText());
  EXPECT_EQ(copy.params().mode, Mode::Mip);
  EXPECT_DOUBLE_EQ(copy.params().clip.hi.x, 0.5);
  EXPECT_EQ(copy.quality().resolution, glm::ivec2(640, 480));
  EXPECT_EQ(copy.quality().preset, "reference");
  // Bad lines, an unknown quality preset and an older version's step scale are skipped.
  copy.fromText("mode=banana\nnot a line\nzoom=2\nui-quality=ultra\nui-step-scale=2\n");
  EXPECT_EQ(copy.params().mode, Mode::Mip);
  EXPECT_DOUBLE_EQ(copy.params().camera.zoom, 2.0);
  EXPECT_EQ(copy.quality().preset, "reference");
  copy.fromText("ui-quality=\n");
  EXPECT_EQ(copy.quality().preset, "");  // custom
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

TEST(RenderState, CommandLineValuesKeepTheWorkstationsRules) {
  RenderStateModel m;
  m.setQualityPreset("balanced");  // a preset chosen before: flags without a step keep it
  m.setPresetShift(300.0);         // from saved state, tuned for another preset
  int notified = 0;
  m.changed.connect([&](unsigned what) { notified += what == kAll; });
  m.applyValues({{"preset", "CT-Bone"}, {"size", "320x240"}, {"azimuth", "40"}});
  EXPECT_EQ(notified, 1);
  EXPECT_EQ(m.params().mode, Mode::Dvr);     // CT-Bone's mode
  EXPECT_EQ(m.params().presetShiftHu, 0.0);  // dropped with the old preset
  EXPECT_EQ(m.params().camera.azimuthDeg, 40.0);
  EXPECT_EQ(m.quality().resolution, glm::ivec2(320, 240));  // --size is the resolution choice
  EXPECT_EQ(m.params().width, RenderParams{}.width);
  EXPECT_EQ(m.quality().preset, "balanced");  // no step, refine or jitter given
  m.applyValues({{"refine", "8"}});
  EXPECT_EQ(m.quality().preset, "");  // an explicit refinement wins over the preset's
  EXPECT_EQ(m.params().refine, 8);
  // A bad value leaves the state as it was.
  EXPECT_THROW(m.applyValues({{"azimuth", "10"}, {"zoom", "-1"}}), Error);
  EXPECT_EQ(m.params().camera.azimuthDeg, 40.0);
}

// Issue 41 item 6: the sample CT's 5 mm slices opened as a 400 HU iso surface at 1.5-voxel
// steps, striped and holed where the thin skull dips below the threshold between slices.
TEST(RenderState, AFirstStartOpensDvrCtBoneAtHalfVoxelStepsWithJitter) {
  RenderStateModel m;
  const RenderParams& p = m.params();
  EXPECT_EQ(p.mode, Mode::Dvr);
  EXPECT_EQ(p.preset, "CT-Bone");
  EXPECT_EQ(p.interp, Interp::Linear);
  EXPECT_EQ(p.gradient, Gradient::ZuckerHummel);
  EXPECT_TRUE(p.jitter);
  EXPECT_TRUE(p.shading);
  EXPECT_EQ(m.quality().preset, "");  // custom: the step and jitter are no preset's
  // The sample's smallest spacing is 0.902 mm: a still steps 0.451 mm, a drag 2 voxels.
  const double h = 0.90234375;
  RenderParams still = planFrame(p, m.quality(), {640, 480}, false, h);
  EXPECT_DOUBLE_EQ(still.stepMm, 0.5 * h);
  EXPECT_TRUE(still.jitter);
  EXPECT_EQ(still.width, 640);
  RenderParams drag = planFrame(p, m.quality(), {640, 480}, true, h);
  EXPECT_DOUBLE_EQ(drag.stepMm, findQualityPreset("interactive").stepVoxels * h);
  EXPECT_FALSE(drag.jitter);
  // Saved preferences (another user's iso look) still win over it.
  RenderStateModel iso;
  iso.update(kAppearance, [](RenderParams& q) { q.mode = Mode::Iso; });
  RenderStateModel restored;
  applyPreferences(restored, preferencesText(iso));
  EXPECT_EQ(restored.params().mode, Mode::Iso);
  EXPECT_EQ(restored.params().preset, "");
}

// Issue 41 item 11: with lighting cinematic the iso controls stayed while the image was the
// dvr classification's; MIP showed a Gradient control it does not use.
TEST(RenderControls, EachControlShowsWhereItChangesTheImage) {
  RenderParams p;
  p.mode = Mode::Iso;
  RenderControls c = renderControlsFor(p);
  EXPECT_TRUE(c.isoRange);
  EXPECT_FALSE(c.mipWindow);
  EXPECT_TRUE(c.gradient);
  EXPECT_EQ(c.note, "");
  p.mode = Mode::Dvr;
  c = renderControlsFor(p);
  EXPECT_FALSE(c.isoRange);
  EXPECT_FALSE(c.mipWindow);
  EXPECT_TRUE(c.gradient);
  p.mode = Mode::Mip;
  c = renderControlsFor(p);
  EXPECT_FALSE(c.isoRange);
  EXPECT_TRUE(c.mipWindow);
  EXPECT_FALSE(c.gradient);  // nothing is shaded in a MIP
  EXPECT_EQ(c.note, "");
  for (Lighting l : {Lighting::Shadows, Lighting::Ao}) {
    p.lighting = l;
    p.mode = Mode::Iso;
    EXPECT_TRUE(renderControlsFor(p).isoRange);
    EXPECT_EQ(renderControlsFor(p).note, "");
  }
}

TEST(RenderControls, CinematicSaysItRendersDvrAndHidesTheModesControls) {
  RenderParams p;
  p.lighting = Lighting::Cinematic;
  for (Mode mode : {Mode::Iso, Mode::Dvr, Mode::Mip}) {
    p.mode = mode;
    const RenderControls c = renderControlsFor(p);
    EXPECT_FALSE(c.isoRange) << toString(mode);
    EXPECT_FALSE(c.mipWindow) << toString(mode);
    EXPECT_FALSE(c.gradient) << toString(mode);  // isotropic scattering: no gradient
  }
  p.mode = Mode::Iso;
  EXPECT_EQ(renderControlsFor(p).note,
            "Cinematic lighting path-traces the volume as dvr with the iso preset's colour table "
            "(without one: CT-Bone's), not the iso surface: the iso range and the gradient do "
            "not apply. Phong, shadows or ao show the iso surface.");
  p.mode = Mode::Mip;
  EXPECT_EQ(renderControlsFor(p).note,
            "Cinematic lighting path-traces the volume as dvr with CT-Bone's colour table (MIP "
            "presets have none), not a maximum intensity projection: the MIP window and the "
            "gradient do not apply. Phong shows the MIP.");
  p.mode = Mode::Dvr;
  EXPECT_EQ(renderControlsFor(p).note,
            "Cinematic lighting path-traces the volume, scattering light evenly in all "
            "directions: the gradient does not apply.");
}
