#include "voxray/io/segmentation_check.h"

#include <gtest/gtest.h>

#include "voxray/io/error.h"

namespace voxray {
namespace {

Volume smallVolume() {
  Volume v;
  v.dims = {4, 3, 2};
  v.spacingMm = {0.5, 0.5, 3.0};
  v.originMm = {-10.0, 20.0, 5.0};
  v.voxels.assign(v.voxelCount(), 0);
  return v;
}

TEST(Segmentation, GridMapsIndexToPatientAndBack) {
  const auto g = gridOf(smallVolume());
  const glm::dvec3 p = g.toPatient({2.0, 1.0, 1.0});
  EXPECT_DOUBLE_EQ(p.x, -9.0);
  EXPECT_DOUBLE_EQ(p.y, 20.5);
  EXPECT_DOUBLE_EQ(p.z, 8.0);
  const glm::dvec3 back = g.toIndex(p);
  EXPECT_NEAR(back.x, 2.0, 1e-12);
  EXPECT_NEAR(back.z, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(g.voxelVolumeMm3(), 0.75);
}

TEST(Segmentation, ChecksSayWhatIsWrong) {
  const Volume v = smallVolume();
  Segmentation s = emptySegmentation(v);
  EXPECT_NO_THROW(checkSegmentation(s));
  EXPECT_NO_THROW(checkSameGrid(s, v));
  Segment bone, table;
  bone.label = table.label = 1;
  bone.name = "Bone";
  table.name = "Table";
  s.segments = {bone, table};
  try {
    checkSegmentation(s);
    FAIL() << "two segments share label 1";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("Two segments use label 1"), std::string::npos);
  }
  Segmentation shifted = emptySegmentation(v);
  shifted.grid.originMm.z += 1.5;
  try {
    checkSameGrid(shifted, v);
    FAIL() << "origin differs by 1.5 mm";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("does not match the volume"), std::string::npos);
  }
  Segmentation wrongSize = emptySegmentation(v);
  wrongSize.labels.pop_back();
  EXPECT_THROW(checkSegmentation(wrongSize), Error);
}

}  // namespace
}  // namespace voxray
