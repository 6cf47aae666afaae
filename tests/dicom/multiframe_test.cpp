// Enhanced multi-frame CT/MR: per-frame functional groups give position, orientation,
// spacing and rescale.
#include "test_data.h"

namespace voxray {
namespace {

using test::dicomPath;

TEST(DicomMultiFrame, PhilipsEnhancedMr) {
  Volume v = importDicom(dicomPath("edge-cases/philips_enhanced/anatomical/001"));
  EXPECT_EQ(v.dims, glm::ivec3(256, 256, 8));
  EXPECT_NEAR(v.spacingMm.z, 1.2, 1e-4);
  EXPECT_EQ(v.spacingMm.x, 1.0);
  EXPECT_EQ(v.direction[2], glm::dvec3(-1, 0, 0));  // sagittal, slices toward the right
  // Ascending along the normal (-x): the first slice is the frame with the largest x.
  EXPECT_NEAR(v.originMm.x, 100.293579101562, 1e-9);
}

TEST(DicomMultiFrame, PhilipsEnhancedImplicitVr) {
  Volume v = importDicom(dicomPath("edge-cases/philips_enhanced/anatomical/001_implicit"));
  EXPECT_EQ(v.dims, glm::ivec3(256, 256, 8));
  EXPECT_NEAR(v.spacingMm.x, 0.9375, 1e-6);
}

TEST(DicomMultiFrame, SiemensEnhancedMrOblique) {
  Volume v = importDicom(dicomPath("edge-cases/siemens_multiframe/anatomical/001"));
  EXPECT_EQ(v.dims, glm::ivec3(256, 256, 8));
  EXPECT_NEAR(v.spacingMm.x, 0.9375, 1e-9);
  EXPECT_NEAR(v.spacingMm.z, 0.9, 1e-3);
  EXPECT_NEAR(v.direction[0].x, 0.999174, 1e-5);
  EXPECT_NEAR(glm::determinant(v.direction), 1.0, 1e-4);
}

TEST(DicomMultiFrame, HyperfineSharedAndPerFrameGroups) {
  Volume v = importDicom(dicomPath("edge-cases/hyperfine/anatomical/001"));
  EXPECT_EQ(v.dims, glm::ivec3(112, 138, 8));
  EXPECT_NEAR(v.spacingMm.x, 1.59, 1e-9);
  EXPECT_NEAR(v.spacingMm.y, 1.61, 1e-9);
  EXPECT_NEAR(v.spacingMm.z, 5.0, 1e-6);
}

TEST(DicomMultiFrame, EnhancedCtTwoFramesOnRequest) {
  LoadOptions o;
  o.series = "3";
  Volume v = importDicom(dicomPath("pydicom-data/eCT_Supplemental.dcm"), o);
  EXPECT_EQ(v.dims, glm::ivec3(512, 512, 2));
  EXPECT_NEAR(v.spacingMm.z, 10.0, 1e-6);
  EXPECT_EQ(v.direction[0], glm::dvec3(-1, 0, 0));
  EXPECT_EQ(v.unit, "HU");
  EXPECT_DOUBLE_EQ(v.slope, 1.0);
  EXPECT_DOUBLE_EQ(v.intercept, -1024.0 + 32768.0);  // unsigned 16-bit, shifted
  EXPECT_GE(test::physicalMin(v), -1024.0);
}

}  // namespace
}  // namespace voxray
