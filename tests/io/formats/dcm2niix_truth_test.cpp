// NIfTI written by dcm2niix (an independent converter) from the shared DICOM series opens as
// the same volume in space as Voxray's own DICOM import: dims, spacing, origin, directions
// (up to the axis order and flips dcm2niix chooses) and every voxel's physical value.
#include <cmath>

#include "format_test_support.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/load.h"

namespace voxray {
namespace {

using test::dicomData;
using test::TempDir;

void expectNiftiMatchesDicom(const std::string& series, bool gz, double relativeTolerance = 0.0) {
  TempDir dir;
  const std::string nii = test::dcm2niix(dicomData(series), dir.path(), gz);
  ASSERT_FALSE(nii.empty());
  const Volume truth = importDicom(dicomData(series));
  const Volume got = loadVolume(nii);
  // dcm2niix keeps the stored integers and writes the DICOM rescale as scl_slope/scl_inter:
  // exact for whole rescales; a fractional one passes through float32 (NIfTI-1's type).
  test::expectSameInSpace(truth, got, relativeTolerance * std::abs(test::physicalMax(truth)));
  EXPECT_EQ(got.unit, "scanner units");
}

TEST(FormatsDcm2niix, AxialCtPelvisGz) { expectNiftiMatchesDicom("ct-visible-human-pelvis", true); }

TEST(FormatsDcm2niix, AxialCtPelvisUncompressed) {
  expectNiftiMatchesDicom("ct-visible-human-pelvis", false);
}

TEST(FormatsDcm2niix, SagittalMr) {
  // Philips RescaleSlope is fractional: float32 keeps it to 6e-8 relative; allow 1e-6.
  expectNiftiMatchesDicom("edge-cases/philips_enhanced/anatomical/001", true, 1e-6);
}

TEST(FormatsDcm2niix, ObliqueMr) {
  expectNiftiMatchesDicom("edge-cases/siemens_multiframe/anatomical/001", true);
}

// The patient's left stays on the left: a voxel on the patient's left in the DICOM (LPS +x)
// holds the same value at the same LPS point of the NIfTI, which dcm2niix stores in RAS+
// (its x axis the other way round); the mirrored voxel holds a different value, so a
// left/right flip would fail here.
TEST(FormatsDcm2niix, LeftStaysLeft) {
  TempDir dir;
  const std::string nii = test::dcm2niix(dicomData("ct-visible-human-pelvis"), dir.path(), true);
  const Volume truth = importDicom(dicomData("ct-visible-human-pelvis"));
  const Volume got = loadVolume(nii);
  const glm::ivec3 left(400, 300, 75), mirrored(truth.dims.x - 1 - 400, 300, 75);
  const glm::dvec3 marker = test::voxelCentre(truth, glm::dvec3(left));
  const glm::dvec3 centre = test::voxelCentre(truth, glm::dvec3(truth.dims - 1) * 0.5);
  ASSERT_GT(marker.x - centre.x, 100.0) << "the DICOM's column 400 is on the patient's left";
  const double value = truth.toPhysical(truth.at(left.x, left.y, left.z));
  ASSERT_NE(value, truth.toPhysical(truth.at(mirrored.x, mirrored.y, mirrored.z)));
  const glm::dmat3 steps = got.direction * glm::dmat3(glm::dvec3(got.spacingMm.x, 0, 0),
                                                      glm::dvec3(0, got.spacingMm.y, 0),
                                                      glm::dvec3(0, 0, got.spacingMm.z));
  const glm::ivec3 i(glm::round(glm::inverse(steps) * (marker - got.originMm)));
  ASSERT_TRUE(glm::all(glm::greaterThanEqual(i, glm::ivec3(0))) &&
              glm::all(glm::lessThan(i, got.dims)));
  EXPECT_GT(test::voxelCentre(got, glm::dvec3(i)).x - centre.x, 100.0);
  EXPECT_EQ(got.toPhysical(got.at(i.x, i.y, i.z)), value);
}

}  // namespace
}  // namespace voxray
