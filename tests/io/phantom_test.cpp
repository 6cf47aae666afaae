// The built-in head phantom: geometry, tissue values and a left/right asymmetry.
#include <gtest/gtest.h>

#include "test_support.h"
#include "voxray/io/phantom.h"

namespace voxray {
namespace {

// Voxel index of an LPS position (direction is identity).
glm::ivec3 voxelAt(const Volume& v, glm::dvec3 mm) {
  return glm::ivec3(glm::round((mm - v.originMm) / v.spacingMm));
}
int16_t valueAt(const Volume& v, glm::dvec3 mm) {
  const glm::ivec3 i = voxelAt(v, mm);
  return v.at(i.x, i.y, i.z);
}

TEST(Phantom, Geometry) {
  const Volume v = makeHeadPhantom(128);
  EXPECT_EQ(v.dims, glm::ivec3(128));
  EXPECT_EQ(v.voxels.size(), 128u * 128u * 128u);
  EXPECT_EQ(v.spacingMm, glm::dvec3(2.0));
  EXPECT_EQ(v.extentMm(), glm::dvec3(256.0));
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
  EXPECT_EQ(v.originMm, glm::dvec3(-127.0));  // centred: voxel 64 is at +1 mm
  EXPECT_EQ(v.slope, 1.0);
  EXPECT_EQ(v.intercept, 0.0);
}

TEST(Phantom, TissueValues) {
  const Volume v = makeHeadPhantom();
  ASSERT_EQ(v.dims, glm::ivec3(256));
  const int16_t centre = valueAt(v, {0, 0, 0});
  EXPECT_GE(centre, 30);
  EXPECT_LE(centre, 45);
  // Corners and the space beside the head are air.
  EXPECT_EQ(v.at(0, 0, 0), -1000);
  EXPECT_EQ(v.at(255, 255, 255), -1000);
  EXPECT_EQ(valueAt(v, {110, 0, 0}), -1000);
  // Through the skull along +x, -x and +z: the shell is bone (semi-axes 0.55 and 0.50 of
  // the 128 mm half box at the sides).
  EXPECT_GT(valueAt(v, {67.5, 4, 5}), 700);
  EXPECT_GT(valueAt(v, {-67.5, 4, 5}), 700);
  EXPECT_GT(valueAt(v, {0, 4, 103.5}), 700);
  // Scalp outside the skull is soft tissue.
  EXPECT_EQ(valueAt(v, {74, 4, 3}), 40);
  // A lateral ventricle holds CSF.
  EXPECT_EQ(valueAt(v, {12.8, -2.6, 15.4}), 5);
  const ValueRange r = storedRange(v);
  EXPECT_EQ(r.min, -1000);
  EXPECT_GE(r.max, 1000);
  EXPECT_LE(r.max, 1200);
}

TEST(Phantom, LesionOnPatientsLeft) {
  const Volume v = makeHeadPhantom();
  const PhantomLesion lesion = headPhantomLeftLesion();
  EXPECT_GT(lesion.centreMm.x, 20.0);  // +x is the patient's left in LPS
  EXPECT_EQ(valueAt(v, lesion.centreMm), lesion.hu);
  const glm::dvec3 mirrored{-lesion.centreMm.x, lesion.centreMm.y, lesion.centreMm.z};
  const int16_t other = valueAt(v, mirrored);
  EXPECT_NE(other, lesion.hu);
  EXPECT_GE(other, 30);  // brain on the right
  EXPECT_LE(other, 45);
}

TEST(Phantom, NosePointsAnterior) {
  const Volume v = makeHeadPhantom();
  // Anterior is -y: the nose sticks out in front of the face, the back of the head does not.
  EXPECT_EQ(valueAt(v, {0, -105, -18}), 40);
  EXPECT_EQ(valueAt(v, {0, 105, -18}), -1000);
}

TEST(Phantom, DeterministicAndSizeChecked) {
  EXPECT_EQ(test::checksum(makeHeadPhantom(64)), test::checksum(makeHeadPhantom(64)));
  EXPECT_THROW(makeHeadPhantom(0), Error);
  EXPECT_THROW(makeHeadPhantom(100000), Error);
}

}  // namespace
}  // namespace voxray
