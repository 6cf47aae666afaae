// Rescale per slice, padding, signedness and non-integral slopes.
#include <cmath>

#include "test_data.h"

namespace voxray {
namespace {

using test::anyContains;
using test::dicomPath;

TEST(DicomValues, PerSliceRescaleKeptWithinHalfAStep) {
  const std::string dir = "edge-cases/generic/anatomical/002_non_isotropic/";
  Volume v = importDicom(dicomPath(dir));
  ASSERT_EQ(v.dims, glm::ivec3(64, 28, 4));
  EXPECT_TRUE(anyContains(v.warnings, "rescale differs between slices"));
  EXPECT_NEAR(v.slope, 0.0010206557, 1e-12);  // the finest slice step
  const char* files[] = {"001.dcm", "002.dcm", "003.dcm", "004.dcm"};
  double worst = 0;
  for (int k = 0; k < 4; ++k) {
    Volume s = importDicom(dicomPath(dir + files[k]));  // exact: its own slope
    for (int y = 0; y < 28; ++y)
      for (int x = 0; x < 64; ++x)
        worst =
            std::max(worst, std::abs(v.toPhysical(v.at(x, y, k)) - s.toPhysical(s.at(x, y, 0))));
  }
  EXPECT_LE(worst, v.slope / 2 + 1e-9);
}

TEST(DicomValues, NonIntegralSlopeKeptInTheVolume) {
  Volume v = importDicom(dicomPath("edge-cases/philips_enhanced/anatomical/001"));
  EXPECT_DOUBLE_EQ(v.slope, 4.25885225885225);
  EXPECT_DOUBLE_EQ(v.intercept, 0.0);
  EXPECT_NE(v.unit, "HU");  // MR stays in scanner units
}

TEST(DicomValues, Unsigned16BitShiftedNotClipped) {
  Volume v = importDicom(dicomPath("edge-cases/hyperfine/anatomical/001"));
  EXPECT_DOUBLE_EQ(v.intercept, 32768.0);
  EXPECT_DOUBLE_EQ(test::physicalMin(v), 0.0);
  EXPECT_DOUBLE_EQ(test::physicalMax(v), 254.0);
  EXPECT_EQ(v.sourceType, "u16");
}

TEST(DicomValues, Unsigned12BitWithIntercept) {
  Volume v = importDicom(dicomPath("ct-philips-phantom"));
  EXPECT_EQ(v.sourceType, "u12");
  EXPECT_DOUBLE_EQ(v.slope, 1.0);
  EXPECT_DOUBLE_EQ(test::physicalMax(v), 782.0);
}

TEST(DicomValues, PaddingBecomesAir) {
  Volume v = importDicom(dicomPath("ct-ge-tilt/01.dcm"));
  EXPECT_EQ(v.sourceType, "i16");
  EXPECT_DOUBLE_EQ(test::physicalMin(v), -1024.0);  // stored -1500 is padding
}

}  // namespace
}  // namespace voxray
