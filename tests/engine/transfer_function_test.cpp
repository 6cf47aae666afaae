#include <gtest/gtest.h>

#include "frame_setup.h"  // engine-internal: how a frame picks its transfer function
#include "test_volumes.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/io/error.h"

namespace voxray {

TEST(TransferFunction, LinearBetweenPointsAndConstantBeyond) {
  TransferFunction tf{{{0.0, {0, 0, 0, 0}}, {100.0, {1, 0.5, 0, 1}}}};
  EXPECT_DOUBLE_EQ(tf.evaluate(50.0).r, 0.5);
  EXPECT_DOUBLE_EQ(tf.evaluate(50.0).g, 0.25);
  EXPECT_DOUBLE_EQ(tf.evaluate(-1e9).a, 0.0);
  EXPECT_DOUBLE_EQ(tf.evaluate(1e9).a, 1.0);
}

TEST(TransferFunction, CoincidentPointsMakeAStepWithoutNaN) {
  TransferFunction tf{{{0.0, {0, 0, 0, 0}},
                       {100.0, {0, 0, 0, 0.2}},
                       {100.0, {1, 1, 1, 0.9}},
                       {200.0, {1, 1, 1, 1}}}};
  EXPECT_DOUBLE_EQ(tf.evaluate(99.999).a, 0.2 * 0.99999);
  EXPECT_DOUBLE_EQ(tf.evaluate(100.0).a, 0.9);
  EXPECT_NEAR(tf.evaluate(150.0).a, 0.95, 1e-12);
}

TEST(TransferFunction, LutIsExactAtEveryStoredValueWhenItFits) {
  Volume v = test::rampX({64, 2, 2}, -100.0, 3.0);  // stored -100 ... 89
  v.slope = 2.0;
  v.intercept = 10.0;  // physical = 2 * stored + 10
  TransferFunction tf{{{-150.0, {0, 0, 0, 0}}, {150.0, {1, 1, 1, 1}}}};
  Lut lut = bakeLut(tf, v);
  ASSERT_EQ(lut.rgba.size(), 190u);  // one entry per stored unit
  for (int s = -100; s <= 89; s += 7) {
    double expected = tf.evaluate(2.0 * s + 10.0).a;
    EXPECT_NEAR(lut.lookup(s).a, expected, 1e-6) << "stored " << s;
  }
}

TEST(Presets, AllBuiltinPresetsParseAndTheIssueNamesExist) {
  for (const char* name : {"CT-Bone", "CT-Muscle", "CT-Skin", "MR-Default", "Iso-Bone", "Iso-Skin"})
    EXPECT_NO_THROW(findPreset(name)) << name;
  EXPECT_EQ(findPreset("ct-bone").name, "CT-Bone");  // case-insensitive
  EXPECT_DOUBLE_EQ(findPreset("Iso-Bone").isoLo, 400.0);
  try {
    findPreset("CT-Nonsense");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("CT-Bone"), std::string::npos) << e.what();
  }
}

TEST(Presets, BrokenPresetSaysWhatIsWrong) {
  try {
    parsePreset(R"({"name":"x","points":[[0,1,1]]})", "my.json");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("my.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("[hu, r, g, b, opacity]"), std::string::npos);
  }
}

}  // namespace voxray

namespace voxray {
TEST(TransferFunction, PresetShiftMovesEveryControlPoint) {
  RenderParams p;
  p.mode = Mode::Dvr;
  p.preset = "CT-Bone";
  p.presetShiftHu = 100.0;
  const TransferFunction& original = findPreset("CT-Bone").tf;
  TransferFunction shifted = frameTransferFunction(p);
  ASSERT_EQ(shifted.points.size(), original.points.size());
  for (double hu : {-200.0, 0.0, 300.0, 741.0, 2000.0})
    EXPECT_DOUBLE_EQ(shifted.evaluate(hu).a, original.evaluate(hu - 100.0).a) << hu;
}
}  // namespace voxray
