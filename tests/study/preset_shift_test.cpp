// The transfer-function shift slider's model side: edits, limits, presets and saved state.
#include <gtest/gtest.h>

#include "render_state_model.h"

using namespace voxray;

TEST(PresetShift, ChangesTheParamsAndNotifiesAppearance) {
  RenderStateModel m;
  m.applyPreset("CT-Bone");
  unsigned seen = 0;
  m.changed.connect([&](unsigned what) { seen |= what; });
  m.setPresetShift(-250.0);
  EXPECT_DOUBLE_EQ(m.params().presetShiftHu, -250.0);
  EXPECT_EQ(seen, unsigned(kAppearance));   // the scheduler renders a new frame on this
  EXPECT_EQ(m.params().preset, "CT-Bone");  // the preset itself stays
}

TEST(PresetShift, IsClampedToTheSliderRange) {
  RenderStateModel m;
  m.setPresetShift(5000.0);
  EXPECT_DOUBLE_EQ(m.params().presetShiftHu, kPresetShiftLimitHu);
  m.setPresetShift(-5000.0);
  EXPECT_DOUBLE_EQ(m.params().presetShiftHu, -kPresetShiftLimitHu);
  m.fromText("preset-shift=99999\n");  // saved state edited by hand
  EXPECT_DOUBLE_EQ(m.params().presetShiftHu, kPresetShiftLimitHu);
}

TEST(PresetShift, ChoosingAPresetStartsFromNoShift) {
  RenderStateModel m;
  m.applyPreset("CT-Bone");
  m.setPresetShift(300.0);
  m.applyPreset("CT-Skin");
  EXPECT_DOUBLE_EQ(m.params().presetShiftHu, 0.0);
}

TEST(PresetShift, PersistsWithTheRenderState) {
  RenderStateModel m;
  m.applyPreset("CT-Muscle");
  m.setPresetShift(-120.0);
  std::string text = m.toText();
  EXPECT_NE(text.find("preset-shift=-120"), std::string::npos) << text;
  RenderStateModel restored;
  restored.fromText(text);
  EXPECT_EQ(restored.params().preset, "CT-Muscle");
  EXPECT_DOUBLE_EQ(restored.params().presetShiftHu, -120.0);
}
