// Issue 18 item 1 and 2: a study opens from its own defaults (full clip box, framed camera,
// the series' own window), and only preferences survive a restart.
#include <gtest/gtest.h>

#include <sstream>

#include "camera_control.h"
#include "study_state.h"
#include "voxray/engine/param_spec.h"
#include "voxray/io/phantom.h"

#ifdef VOXRAY_HAS_DICOM
#include "voxray/io/dicom_import.h"
#endif

using namespace voxray;

namespace {

std::shared_ptr<const Volume> phantom(int size) {
  return std::make_shared<const Volume>(makeHeadPhantom(size));
}

// Where the user looked and what they cut away in the study on screen.
void lookAround(AppModels& m) {
  m.render.update(kCamera | kClip | kLight, [](RenderParams& p) {
    p.clip.lo = {0.5, 0.0, 0.0};  // half the volume cut away
    p.camera.azimuthDeg = 40.0;
    p.camera.elevationDeg = -20.0;
    p.camera.zoom = 2.5;
    p.camera.panMm = {30.0, -12.0};
    p.camera.distanceMm = 900.0;
    p.light.position = {100.0, 0.0, 50.0};
    p.light.followCamera = false;
  });
  m.windowLevel.set({1500.0, -600.0});
  m.crosshair.setVoxel({1, 2, 3});
}

// The user's choices of look, which carry over.
void choosePreferences(AppModels& m) {
  m.render.applyPreset("CT-Bone");
  m.render.setPresetShift(-150.0);
  m.render.setQualityPreset("reference");
  m.render.update(kAppearance | kCamera, [](RenderParams& p) {
    p.camera.projection = Projection::Orthographic;
    p.light.ambient = 0.3;
  });
}

// The lines of the per-study parameters, "size" aside (the view decides it).
std::string studyLines(const RenderParams& p) {
  std::istringstream in(toText(p));
  std::string line, out;
  while (std::getline(in, line)) {
    std::string key = line.substr(0, line.find('='));
    if (!isPreference(key) && key != "size") out += line + "\n";
  }
  return out;
}

}  // namespace

TEST(StudyState, EveryPreferenceIsARenderParameter) {
  for (const auto& key : preferenceKeys()) EXPECT_NO_THROW(findRenderParamSpec(key)) << key;
  EXPECT_FALSE(isPreference("clip"));
  EXPECT_FALSE(isPreference("zoom"));
  EXPECT_FALSE(isPreference("light"));
  EXPECT_TRUE(isPreference("preset"));
  EXPECT_TRUE(isPreference("projection"));
}

TEST(StudyState, NextStudyOpensFromItsOwnDefaults) {
  AppModels m;
  openStudy(m, phantom(32), "A");
  choosePreferences(m);
  lookAround(m);
  const RenderParams chosen = m.render.params();
  ASSERT_FALSE(chosen.clip.isFull());

  auto b = std::make_shared<Volume>(makeHeadPhantom(24));
  b->window = DisplayWindow{350.0, 45.0, "MEDIASTINUM"};
  int documentChanges = 0;
  m.document.changed.connect([&] {
    ++documentChanges;
    // Whoever hears of the new volume sees its state already.
    EXPECT_TRUE(m.render.params().clip.isFull());
    EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 350.0);
  });
  openStudy(m, b, "B");
  EXPECT_EQ(documentChanges, 1);
  EXPECT_EQ(m.document.name(), "B");

  const RenderParams& p = m.render.params();
  EXPECT_TRUE(p.clip.isFull());
  EXPECT_DOUBLE_EQ(p.camera.azimuthDeg, 0.0);
  EXPECT_DOUBLE_EQ(p.camera.elevationDeg, 0.0);
  EXPECT_DOUBLE_EQ(p.camera.zoom, 1.0);
  EXPECT_DOUBLE_EQ(p.camera.distanceMm, 0.0);  // framed: the whole volume in view
  EXPECT_EQ(p.camera.panMm, glm::dvec2(0.0));
  EXPECT_EQ(p.light.position, LightParams().position);
  EXPECT_TRUE(p.light.followCamera);
  EXPECT_EQ(studyLines(p), studyLines(RenderParams{}));  // every per-study parameter
  EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 350.0);  // B's own window
  EXPECT_DOUBLE_EQ(m.windowLevel.value().level, 45.0);
  EXPECT_EQ(m.crosshair.voxel(), glm::ivec3(12));  // the centre of B

  // The preferences stayed.
  EXPECT_EQ(p.preset, "CT-Bone");
  EXPECT_DOUBLE_EQ(p.presetShiftHu, -150.0);
  EXPECT_EQ(p.camera.projection, Projection::Orthographic);
  EXPECT_DOUBLE_EQ(p.light.ambient, 0.3);
  EXPECT_EQ(m.render.quality().preset, "reference");
  EXPECT_EQ(preferencesText(m.render), [&] {
    RenderStateModel same;
    same.fromText(toText(chosen) + "ui-resolution=0,0\nui-quality=reference\n");
    return preferencesText(same);
  }());
}

TEST(StudyState, RestartRestoresPreferencesOnly) {
  AppModels before;
  openStudy(before, phantom(32), "A");
  choosePreferences(before);
  lookAround(before);
  const std::string saved = preferencesText(before.render);
  EXPECT_EQ(saved.find("clip="), std::string::npos);
  EXPECT_EQ(saved.find("zoom="), std::string::npos);
  EXPECT_EQ(saved.find("azimuth="), std::string::npos);
  EXPECT_EQ(saved.find("light="), std::string::npos);

  AppModels after;  // a new start over the same saved text
  applyPreferences(after.render, saved);
  EXPECT_EQ(after.render.params().preset, "CT-Bone");
  EXPECT_DOUBLE_EQ(after.render.params().presetShiftHu, -150.0);
  EXPECT_EQ(after.render.params().camera.projection, Projection::Orthographic);
  EXPECT_EQ(after.render.quality().preset, "reference");
  EXPECT_TRUE(after.render.params().clip.isFull());
  EXPECT_DOUBLE_EQ(after.render.params().camera.zoom, 1.0);

  // An older version saved the whole state: its clip box and camera stay behind.
  AppModels old;
  applyPreferences(old.render, before.render.toText());
  EXPECT_EQ(old.render.params().preset, "CT-Bone");
  EXPECT_EQ(studyLines(old.render.params()), studyLines(RenderParams{}));
}

TEST(StudyState, AVolumeThatCannotBeShownGivesThePreviousOneBackAsItWas) {
  AppModels m;
  openStudy(m, phantom(32), "A");
  lookAround(m);
  const std::string looked = studyLines(m.render.params());
  auto b = std::make_shared<Volume>(makeHeadPhantom(16));
  b->window = DisplayWindow{80.0, 40.0, ""};
  openStudy(m, b, "B");
  ASSERT_NE(studyLines(m.render.params()), looked);
  restorePreviousStudy(m);  // B's upload failed
  EXPECT_EQ(m.document.name(), "A");
  EXPECT_EQ(studyLines(m.render.params()), looked);
  EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 1500.0);
  EXPECT_DOUBLE_EQ(m.windowLevel.value().level, -600.0);
  EXPECT_EQ(m.crosshair.dims(), glm::ivec3(32));
  EXPECT_EQ(m.crosshair.voxel(), glm::ivec3(1, 2, 3));
}

TEST(StudyState, CommandLineValuesApplyToTheVolumeItOpens) {
  AppModels m;
  m.render.applyValues({{"step", "0.7"}});  // a preference, applied when given
  lookAround(m);
  openStudy(m, phantom(16), "A",
            {{"azimuth", "30"}, {"clip", "0,0.5,0,1,0,1"}, {"step", "2"}, {"zoom", "1.5"}});
  const RenderParams& p = m.render.params();
  EXPECT_DOUBLE_EQ(p.camera.azimuthDeg, 30.0);
  EXPECT_DOUBLE_EQ(p.clip.hi.x, 0.5);
  EXPECT_DOUBLE_EQ(p.camera.zoom, 1.5);
  EXPECT_DOUBLE_EQ(p.camera.panMm.x, 0.0);  // not given: the study's default
  EXPECT_DOUBLE_EQ(p.stepMm, 0.7);          // preferences among them are not applied again
}

TEST(StudyState, InitialWindowFromTheFileThenModality) {
  Volume v = makeHeadPhantom(8);
  v.window = DisplayWindow{350.0, 40.0, "WINDOW1"};
  InitialWindow w = initialWindow(v);
  EXPECT_DOUBLE_EQ(w.wl.width, 350.0);
  EXPECT_DOUBLE_EQ(w.wl.level, 40.0);
  EXPECT_NE(w.source.find("WINDOW1"), std::string::npos);
  EXPECT_NE(w.source.find("DICOM window"), std::string::npos);

  v.window.reset();
  v.modality = "CT";
  w = initialWindow(v);
  EXPECT_DOUBLE_EQ(w.wl.width, 400.0);
  EXPECT_DOUBLE_EQ(w.wl.level, 40.0);
  EXPECT_NE(w.source.find("CT default"), std::string::npos);

  Volume mr;
  mr.dims = {2, 1, 1};
  mr.voxels = {100, 500};
  mr.slope = 2.0;
  mr.intercept = 10.0;  // physical 210 ... 1010
  mr.modality = "MR";
  w = initialWindow(mr);
  EXPECT_DOUBLE_EQ(w.wl.width, 800.0);
  EXPECT_DOUBLE_EQ(w.wl.level, 610.0);
  EXPECT_NE(w.source.find("value range (MR"), std::string::npos);
  mr.modality.clear();  // raw data without a rescale: nothing says what it is
  mr.unit = "value";    // as the raw importer labels it
  EXPECT_NE(initialWindow(mr).source.find("modality unknown"), std::string::npos);
}

TEST(StudyState, TheSourceShowsBesideTheWindowUntilTheUserChangesIt) {
  AppModels m;
  auto v = std::make_shared<Volume>(makeHeadPhantom(8));
  v->window = DisplayWindow{1639.0, 763.0, "Algo1"};
  openStudy(m, v, "MR");
  EXPECT_EQ(m.windowLevel.source(), "Algo1 (DICOM window)");
  EXPECT_EQ(formatWindowLevel(m.windowLevel.value(), m.windowLevel.source()),
            "W 1639  L 763\nAlgo1 (DICOM window)");
  m.windowLevel.set({80.0, 40.0});
  EXPECT_EQ(m.windowLevel.source(), "");
  EXPECT_EQ(formatWindowLevel(m.windowLevel.value(), m.windowLevel.source()), "W 80  L 40");
}

#ifdef VOXRAY_HAS_DICOM
TEST(StudyState, DicomSeriesOpensWithItsWindowOrTheCtDefault) {
  const std::string data = std::string(VOXRAY_DATA_DIR) + "/dicom/";
  AppModels m;
  openStudy(m, std::make_shared<const Volume>(importDicom(data + "ct-ge-tilt")), "tilt");
  EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 100.0);  // WindowWidth of the header
  EXPECT_DOUBLE_EQ(m.windowLevel.value().level, 35.0);   // WindowCenter
  EXPECT_EQ(m.windowLevel.source(), "DICOM window");
  m.windowLevel.set({1800.0, 400.0});
  openStudy(m, std::make_shared<const Volume>(importDicom(data + "ct-visible-human-pelvis")),
            "pelvis");
  EXPECT_DOUBLE_EQ(m.windowLevel.value().width, 400.0);  // CT without a window
  EXPECT_DOUBLE_EQ(m.windowLevel.value().level, 40.0);
  EXPECT_NE(m.windowLevel.source().find("CT default"), std::string::npos);
}
#endif

TEST(StudyState, SliceInterpolationIsAPreference) {
  AppModels m;
  EXPECT_EQ(m.render.sliceInterp(), Interp::Linear);  // the default: no staircases
  unsigned heard = 0;
  m.render.changed.connect([&](unsigned what) { heard = what; });
  m.render.setSliceInterp(Interp::Nearest);
  EXPECT_EQ(heard, unsigned(kSlices));  // the slice views hear it; no new 3D frame
  openStudy(m, phantom(16), "A");
  EXPECT_EQ(m.render.sliceInterp(), Interp::Nearest);  // carries over to the next study
  const std::string saved = preferencesText(m.render);
  EXPECT_NE(saved.find("ui-slice-interp=nearest\n"), std::string::npos) << saved;
  AppModels restarted;
  applyPreferences(restarted.render, saved);
  EXPECT_EQ(restarted.render.sliceInterp(), Interp::Nearest);
  applyPreferences(restarted.render, "ui-slice-interp=cubic\n");  // bad: kept as it was
  EXPECT_EQ(restarted.render.sliceInterp(), Interp::Nearest);
}
