// The ray step's one conversion (voxray/engine/step.h): mm <-> units of the smallest voxel
// spacing, and the default of stepMm 0.
#include <gtest/gtest.h>

#include "voxray/engine/quality.h"
#include "voxray/engine/step.h"

namespace voxray {

TEST(Step, ZeroMmIsHalfTheSmallestSpacingInBothUnits) {
  for (const double h : {0.7, 0.8, 1.0 / 3.0, 0.48828125, 2.0}) {
    EXPECT_EQ(effectiveStepMm(0.0, h), 0.5 * h) << h;
    EXPECT_EQ(stepVoxelsOf(0.0, h), 0.5) << h;  // exactly: the controller's 2 % match
    EXPECT_EQ(stepVoxelsOf(-1.0, h), 0.5) << h;
    EXPECT_EQ(stepMmOf(kDefaultStepVoxels, h), effectiveStepMm(0.0, h)) << h;
  }
  EXPECT_EQ(stepMmOf(0.0, 0.7), 0.0);  // 0 voxels stays 0 mm: the default
}

TEST(Step, MillimetresAndVoxelsRoundTrip) {
  for (const double h : {0.7, 0.8, 1.0 / 3.0, 0.48828125, 2.0})
    for (const double voxels : {1.0 / 16, 0.25, 0.5, 1.5, 2.0, 2.5, 4.0}) {
      const double mm = stepMmOf(voxels, h);
      EXPECT_DOUBLE_EQ(mm, voxels * h);
      EXPECT_EQ(effectiveStepMm(mm, h), mm);  // a set step is marched as it is
      EXPECT_DOUBLE_EQ(stepVoxelsOf(mm, h), voxels) << h << " " << voxels;
    }
}

TEST(Step, QualityPresetStepIsTheConversionOfItsVoxels) {
  const QualityPreset& q = findQualityPreset("interactive");
  RenderParams p;
  p.stepMm = 0.3;  // the preset's step replaces the user's
  const RenderParams framed = applyQuality(p, q, 0.7);
  EXPECT_DOUBLE_EQ(framed.stepMm, 2.0 * 0.7);  // resources/quality/interactive.json: 2 voxels
  EXPECT_DOUBLE_EQ(stepVoxelsOf(framed.stepMm, 0.7), q.stepVoxels);
}

}  // namespace voxray
