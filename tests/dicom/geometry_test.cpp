// Slice order, spacing from positions, LPS geometry, tilt and uneven-gap resampling.
#include <cmath>
#include <cstring>

#include "test_data.h"

namespace voxray {
namespace {

using test::anyContains;
using test::dicomPath;

bool sameSlice(const Volume& v, int k, const Volume& single) {
  const size_t n = size_t(v.dims.x) * v.dims.y;
  if (single.voxelCount() != n) return false;
  for (size_t i = 0; i < n; ++i)
    if (v.toPhysical(v.voxels[k * n + i]) != single.toPhysical(single.voxels[i])) return false;
  return true;
}

TEST(DicomGeometry, PelvisSortedByPositionNotFileName) {
  Volume v = importDicom(dicomPath("ct-visible-human-pelvis"));
  EXPECT_EQ(v.dims, glm::ivec3(512, 512, 150));
  EXPECT_EQ(v.spacingMm, glm::dvec3(1.0, 1.0, 1.0));
  EXPECT_EQ(v.originMm, glm::dvec3(0.0, 0.0, 900.0));
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
  EXPECT_EQ(v.unit, "HU");
  EXPECT_DOUBLE_EQ(test::physicalMin(v), -1024.0);
  EXPECT_DOUBLE_EQ(test::physicalMax(v), 1531.0);  // stored 2555 - 1024, as in the files
  EXPECT_TRUE(v.warnings.empty());
  // vhf.0001.dcm lies at z = 998 mm: slice 98, not slice 0.
  Volume first = importDicom(dicomPath("ct-visible-human-pelvis/vhf.0001.dcm"));
  EXPECT_EQ(first.originMm.z, 998.0);
  EXPECT_TRUE(sameSlice(v, 98, first));
  EXPECT_FALSE(sameSlice(v, 0, first));
}

TEST(DicomGeometry, GeTiltDetectedWarnedAndResampledOntoEveryAcquiredPixel) {
  Volume v = importDicom(dicomPath("ct-ge-tilt"));
  EXPECT_TRUE(anyContains(v.warnings, "gantry tilt of 18.5 degrees")) << v.warnings.size();
  EXPECT_TRUE(anyContains(v.warnings, "uneven slice gaps (min 1.14 mm, max 7.38 mm)"));
  EXPECT_TRUE(anyContains(v.warnings, "outside the acquired slices and is filled with air"));
  // Orthogonal axial grid. Along z it reaches from the last row of the first slice
  // (z 5.836 mm, its column direction falling 0.3173 per mm over 511 rows of 0.488 mm) to
  // the first row of the last slice (z 157.776), not only over the table positions.
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
  EXPECT_NEAR(v.originMm.z, 5.8360586 - 511 * 0.4882812 * 0.3173047, 1e-4);
  const double lastZ = v.originMm.z + (v.dims.z - 1) * v.spacingMm.z;
  EXPECT_NEAR(lastZ, 157.7760586, 1e-6);
  EXPECT_NEAR(v.spacingMm.x, 0.4882812, 1e-9);
  EXPECT_NEAR(v.spacingMm.y, 0.4882812, 1e-9);
  EXPECT_EQ(v.dims.x, 512);
  // Rows of a tilted slice cover 512 * 0.488 * cos(18.5 deg) = 237 mm along y.
  EXPECT_NEAR(v.dims.y * v.spacingMm.y, 512 * 0.4882812 * std::cos(glm::radians(18.5)), 1.0);
  // Uniform slice spacing no coarser than the median gap (4.22 mm along z).
  EXPECT_LT(v.spacingMm.z, 4.22);
  // PixelPaddingValue -1500 and the grid's corners beyond the slices became air.
  EXPECT_DOUBLE_EQ(test::physicalMin(v), -1024.0);
}

TEST(DicomGeometry, MissingSliceDetectedAndInterpolated) {
  Volume v = importDicom(dicomPath("edge-cases/failing/sliceincrement/001"));
  EXPECT_TRUE(anyContains(v.warnings, "1 slice(s) missing"));
  EXPECT_EQ(v.dims, glm::ivec3(512, 512, 5));
  EXPECT_NEAR(v.spacingMm.z, 5.0, 1e-4);
  EXPECT_NEAR(v.originMm.z, 18.1075, 1e-6);
  // The filled slice (z = 33.1) is the mean of its neighbours (28.1 and 38.1).
  int off = 0;
  for (int y = 0; y < 512; y += 7)
    for (int x = 0; x < 512; x += 7) {
      double mean = 0.5 * (v.at(x, y, 2) + v.at(x, y, 4));
      off += std::abs(v.at(x, y, 3) - mean) > 0.51;
    }
  EXPECT_EQ(off, 0);
}

TEST(DicomGeometry, TiltWithoutGantryTagIsFoundFromPositions) {
  Volume v = importDicom(dicomPath("edge-cases/failing/gantrytilting/001"));
  EXPECT_TRUE(anyContains(v.warnings, "gantry tilt of 14.0 degrees"));
  // Four slices 5 mm apart whose 512 rows of 0.418 mm fall 0.2419 per mm along z: 15 mm
  // of table and 51.7 mm of tilted rows, in 14 steps no longer than the 5 mm gap.
  const double extent = 15.0 + 511 * 0.41796875 * 0.2419218955997;
  EXPECT_EQ(v.dims.z, 15);
  EXPECT_NEAR(v.spacingMm.z, extent / 14, 1e-6);
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
}

TEST(DicomGeometry, SagittalMrKeepsLpsDirections) {
  Volume v = importDicom(dicomPath("edge-cases/generic/anatomical/001"));
  EXPECT_EQ(v.dims, glm::ivec3(256, 256, 4));
  // Rows along +y (anterior to posterior), columns along -z (head to feet), slices along
  // the normal, sorted ascending: the first slice is the one at x = -103.79.
  EXPECT_EQ(v.direction[0], glm::dvec3(0, 1, 0));
  EXPECT_EQ(v.direction[1], glm::dvec3(0, 0, -1));
  EXPECT_EQ(v.direction[2], glm::dvec3(-1, 0, 0));
  EXPECT_NEAR(v.originMm.x, -100.79415804148, 1e-9);
  EXPECT_NEAR(v.spacingMm.z, 1.0, 1e-9);
}

TEST(DicomGeometry, ObliqueMrSpacingFromPositionsNotThickness) {
  Volume v = importDicom(dicomPath("edge-cases/anatomical/001_implicit"));
  EXPECT_EQ(v.dims, glm::ivec3(256, 256, 4));
  EXPECT_NEAR(v.spacingMm.z, 1.0, 1e-3);
  EXPECT_NEAR(glm::determinant(v.direction), 1.0, 1e-6);
  EXPECT_TRUE(v.warnings.empty());
}

}  // namespace
}  // namespace voxray
