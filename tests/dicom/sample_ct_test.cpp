// The embedded sample CT is what resources/sample/make-sample-ct.sh says it is: the shared
// Philips head-phantom series averaged over 2 x 2 pixels, with that series' geometry and
// window, opened through loadVolume's sample name.
#include <cmath>

#include "test_data.h"
#include "voxray/io/load.h"
#include "voxray/io/sample_volume.h"

namespace voxray {
namespace {

TEST(SampleCt, IsTheSharedPhilipsSeriesAveragedOverTwoByTwoPixels) {
  Volume s = loadVolume(kSampleCtInput);
  Volume d = importDicom(test::dicomPath("ct-philips-phantom"));
  ASSERT_EQ(d.dims, glm::ivec3(512, 512, 28));
  ASSERT_EQ(s.dims, glm::ivec3(256, 256, 28));
  EXPECT_EQ(s.spacingMm, glm::dvec3(2 * d.spacingMm.x, 2 * d.spacingMm.y, d.spacingMm.z));
  EXPECT_EQ(s.direction, d.direction);
  // Voxel (0,0,0) of the sample is the centre of the first 2 x 2 block.
  glm::dvec3 expectedOrigin =
      d.originMm + d.direction[0] * (0.5 * d.spacingMm.x) + d.direction[1] * (0.5 * d.spacingMm.y);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(s.originMm[a], expectedOrigin[a], 1e-9);
  EXPECT_EQ(s.slope, d.slope);
  EXPECT_EQ(s.intercept, d.intercept);
  EXPECT_EQ(s.modality, "CT");
  EXPECT_EQ(s.unit, "HU");
  // The sample opens in a bone window (the series says 80/40, a brain window).
  ASSERT_TRUE(s.window && d.window);
  EXPECT_EQ(d.window->width, 80.0);
  EXPECT_EQ(s.window->width, 1500.0);
  EXPECT_EQ(s.window->level, 300.0);
  EXPECT_EQ(s.window->explanation, "Bone");
  EXPECT_EQ(s.window->origin, "the sample's window");
  EXPECT_EQ(d.window->origin, "DICOM window");
  // Every voxel: the mean of its four, rounded half away from zero.
  size_t differing = 0;
  for (int z = 0; z < s.dims.z; ++z)
    for (int y = 0; y < s.dims.y; ++y)
      for (int x = 0; x < s.dims.x; ++x) {
        double mean = (d.at(2 * x, 2 * y, z) + d.at(2 * x + 1, 2 * y, z) +
                       d.at(2 * x, 2 * y + 1, z) + d.at(2 * x + 1, 2 * y + 1, z)) /
                      4.0;
        differing += s.at(x, y, z) != int16_t(std::round(mean));
      }
  EXPECT_EQ(differing, 0u);
  // Nothing identifying: the sample says it is a sample, and carries no patient.
  EXPECT_EQ(s.study.patientName, "");
  EXPECT_EQ(s.study.patientId, "");
  EXPECT_NE(s.study.studyDescription.find("Sample"), std::string::npos);
  EXPECT_NE(sampleCtAttribution().find("BSD-2-Clause"), std::string::npos);
}

}  // namespace
}  // namespace voxray
