// Labels in the panel and messages that must say what is rendered or asked for (issue 18,
// items 7 and 8): the quality figures, the clip axes, the light's unit, error wording.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "clip_box_math.h"
#include "gui_message.h"
#include "light_gizmo.h"
#include "quality_choice.h"
#include "render_state_model.h"
#include "voxray/engine/input_flags.h"
#include "voxray/engine/quality.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/io/orientation.h"
#include "voxray/io/raw_import.h"

using namespace voxray;

TEST(Labels, BalancedMeansOneRenderingFromTheStart) {
  // At start-up "Balanced" rendered central differences; after a visit to Reference the
  // same label meant Zucker-Hummel.
  RenderStateModel m;
  const QualityPreset& balanced = findQualityPreset("balanced");
  m.setQualityPreset("balanced");  // a first start is custom (firstStartLook): no figures
  EXPECT_EQ(m.quality().preset, "balanced");
  EXPECT_EQ(m.params().gradient, balanced.gradient);
  EXPECT_EQ(m.params().interp, balanced.interp);
  EXPECT_EQ(qualityMismatch("balanced", m.params()), "");
  m.setQualityPreset("reference");
  m.setQualityPreset("balanced");
  EXPECT_EQ(m.params().gradient, balanced.gradient);
  // Changed afterwards: the figures are no longer shown as this rendering's.
  m.update(kAppearance, [](RenderParams& p) { p.gradient = Gradient::Central; });
  EXPECT_EQ(qualityMismatch("balanced", m.params()),
            "Not as measured: Central difference gradient (measured with Zucker-Hummel)");
  m.update(kAppearance, [](RenderParams& p) { p.interp = Interp::Nearest; });
  EXPECT_EQ(qualityMismatch("balanced", m.params()),
            "Not as measured: Central difference gradient (measured with Zucker-Hummel); "
            "Nearest sampling (measured with Trilinear)");
  EXPECT_EQ(qualityMismatch("", m.params()), "");  // custom claims no figures
}

TEST(Labels, MeasuredFiguresSayWhereTheyWereMeasured) {
  for (const QualityChoice& c : qualityChoices()) {
    if (c.preset.empty()) continue;
    const QualityPreset& q = findQualityPreset(c.preset);
    ASSERT_FALSE(q.measuredOn.empty()) << c.preset;
    EXPECT_NE(c.measured.find(", measured on " + q.measuredOn), std::string::npos) << c.measured;
  }
  const QualityChoice balanced = qualityChoices()[1];
  EXPECT_EQ(balanced.measured.substr(0, balanced.measured.find(',')),
            "41.8 dB PSNR \u00b7 6.3\u00d7 Reference's speed");
}

TEST(Labels, ModeChangeDropsAPresetMadeForAnotherMode) {
  RenderStateModel m;
  m.applyPreset("CT-Bone");
  m.setPresetShift(200.0);
  EXPECT_EQ(m.params().mode, Mode::Dvr);
  EXPECT_TRUE(presetFitsMode("CT-Bone", Mode::Dvr));
  EXPECT_FALSE(presetFitsMode("CT-Bone", Mode::Mip));
  EXPECT_FALSE(presetFitsMode("no such preset", Mode::Dvr));
  // "CT-Bone" in MIP named a table MIP does not use.
  m.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Mip; });
  EXPECT_EQ(m.params().preset, "");
  EXPECT_EQ(m.params().presetShiftHu, 0.0);
  // A preset of the new mode, and edits that keep the mode, keep it.
  m.applyPreset("CT-MIP");
  m.update(kAppearance, [](RenderParams& p) { p.windowLevel = 300.0; });
  EXPECT_EQ(m.params().preset, "CT-MIP");
  m.applyPreset("Iso-Bone");
  m.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Iso; });
  EXPECT_EQ(m.params().preset, "Iso-Bone");
}

TEST(Labels, ClipAxesNamePatientDirections) {
  // From the low face to the high face of each index axis.
  auto lps = clipAxisLabels(directionFromAxesCode("LPS"));
  EXPECT_EQ(lps[0], "R\u2013L");
  EXPECT_EQ(lps[1], "A\u2013P");
  EXPECT_EQ(lps[2], "I\u2013S");
  auto lpi = clipAxisLabels(directionFromAxesCode("LPI"));  // CThead: slice 1 at the top
  EXPECT_EQ(lpi[2], "S\u2013I");
  auto pil = clipAxisLabels(directionFromAxesCode("PIL"));  // sagittal MRbrain
  EXPECT_EQ(pil[0], "A\u2013P");
  EXPECT_EQ(pil[1], "S\u2013I");
  EXPECT_EQ(pil[2], "R\u2013L");
  // A slightly oblique axis takes the closest patient axis.
  glm::dmat3 tilted(1.0);
  tilted[0] = glm::normalize(glm::dvec3(0.95, 0.1, 0.0));
  tilted[1] = glm::normalize(glm::dvec3(-0.1, 0.95, 0.0));
  EXPECT_EQ(clipAxisLabels(tilted)[0], "R\u2013L");
  EXPECT_EQ(clipAxisLabels(tilted)[1], "A\u2013P");
}

TEST(Labels, LightPositionHasAUnitInEitherFrame) {
  LightPositionUnit fixed = lightPositionUnit(false);
  EXPECT_EQ(fixed.suffix, " mm");
  EXPECT_EQ(fixed.axes[0], "L (x)");
  EXPECT_EQ(fixed.axes[2], "S (z)");
  LightPositionUnit follow = lightPositionUnit(true);
  EXPECT_EQ(follow.suffix, " \u00d7 radius");
  EXPECT_EQ(follow.axes[0], "Right");
  EXPECT_NE(follow.tooltip, fixed.tooltip);
}

TEST(Labels, GuiMessagesNameFieldsNotFlags) {
  // Every raw-input flag of the CLI has a workstation name.
  for (const InputFlagSpec& s : inputFlagSpecs()) EXPECT_NO_THROW(inputFieldLabel(s.key)) << s.key;
  EXPECT_EQ(inputFieldLabel("raw-dims"), "Dimensions x, y, z");

  // A real importer message: the CLI keeps its flag, the GUI names the dialog's field.
  auto file = std::filesystem::temp_directory_path() / "voxray_labels_test.raw";
  {
    std::ofstream out(file, std::ios::binary);
    out << std::string(1000, '\0');
  }
  RawLayout l;
  l.dims = {100, 100, 1};
  std::string cli;
  try {
    importRaw(file.string(), l);
  } catch (const std::exception& e) {
    cli = e.what();
  }
  std::filesystem::remove(file);
  ASSERT_NE(cli.find("--raw-dims"), std::string::npos) << cli;
  std::string gui = guiMessage(cli);
  EXPECT_EQ(gui.find("--raw"), std::string::npos) << gui;
  EXPECT_NE(gui.find("\u201cDimensions x, y, z\u201d"), std::string::npos) << gui;

  // Value hints in the CLI's syntax go with their flag; other text stays as written.
  EXPECT_EQ(guiMessage("check --raw-dims X,Y,Z (Z = 0: count the slices) and --raw-type u8"),
            "check \u201cDimensions x, y, z\u201d (Z = 0: count the slices) and "
            "\u201cSample type\u201d u8");
  EXPECT_EQ(guiMessage("--raw-range: expected FIRST-LAST, e.g. 1-113"),
            "\u201cSlice range\u201d: expected FIRST-LAST, e.g. 1-113");
  EXPECT_EQ(guiMessage("try --device cpu -- or not"), "try --device cpu -- or not");
  EXPECT_EQ(guiMessage("ends with --"), "ends with --");
}
