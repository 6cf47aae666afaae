#include <gtest/gtest.h>

#include "slice_image.h"
#include "voxray/io/phantom.h"

using namespace voxray;

namespace {
using Labels = std::array<std::string, 4>;  // left, right, top, bottom
}

TEST(SliceGeometry, RadiologicalLabelsForLpsAlignedVolume) {
  glm::dmat3 identity(1.0);
  EXPECT_EQ(sliceAxes(identity, Orientation::Axial).labels, (Labels{"R", "L", "A", "P"}));
  EXPECT_EQ(sliceAxes(identity, Orientation::Coronal).labels, (Labels{"R", "L", "S", "I"}));
  EXPECT_EQ(sliceAxes(identity, Orientation::Sagittal).labels, (Labels{"A", "P", "S", "I"}));
  auto axial = sliceAxes(identity, Orientation::Axial);
  EXPECT_EQ(axial.uAxis, 0);
  EXPECT_EQ(axial.vAxis, 1);
  EXPECT_EQ(axial.nAxis, 2);
  EXPECT_FALSE(axial.uFlip);
  EXPECT_FALSE(axial.vFlip);
  auto coronal = sliceAxes(identity, Orientation::Coronal);
  EXPECT_TRUE(coronal.vFlip);  // superior (+z) at the top
}

TEST(SliceGeometry, FlippedAndPermutedAxesStillShowPatientRightOnTheLeft) {
  // i runs to the patient's right (-x), j runs superior (+z), k runs anterior (-y).
  glm::dmat3 dir(glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
  auto axial = sliceAxes(dir, Orientation::Axial);
  EXPECT_EQ(axial.nAxis, 1);  // j is closest to z
  EXPECT_EQ(axial.uAxis, 0);
  EXPECT_TRUE(axial.uFlip);  // i grows to the patient's right = screen left
  EXPECT_EQ(axial.vAxis, 2);
  EXPECT_TRUE(axial.vFlip);  // k grows anterior = screen top
  EXPECT_EQ(axial.labels, (Labels{"R", "L", "A", "P"}));
}

TEST(SliceGeometry, SliceToVoxelRoundTrips) {
  glm::dmat3 dir(glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
  glm::ivec3 dims(30, 20, 10);
  for (auto o : {Orientation::Axial, Orientation::Coronal, Orientation::Sagittal}) {
    auto a = sliceAxes(dir, o);
    glm::dvec3 voxel = sliceToVoxel(a, dims, 3.5, 4.5, 7);
    glm::dvec2 back = voxelToSlice(a, dims, voxel);
    EXPECT_DOUBLE_EQ(back.x, 3.5) << toString(o);
    EXPECT_DOUBLE_EQ(back.y, 4.5) << toString(o);
    EXPECT_DOUBLE_EQ(voxel[a.nAxis], 7) << toString(o);
  }
}

// Picking: a click where the phantom's left-hemisphere lesion shows in the axial view gives
// the lesion's 3D position in patient mm, on the screen's right (patient left).
TEST(SliceGeometry, ClickOnLesionPicksItsPatientPosition) {
  Volume v = makeHeadPhantom(64);
  PhantomLesion lesion = headPhantomLeftLesion();
  glm::dvec3 voxel = (lesion.centreMm - v.originMm) / v.spacingMm;  // direction is identity
  auto axial = sliceAxes(v.direction, Orientation::Axial);
  glm::dvec2 click = voxelToSlice(axial, v.dims, glm::round(voxel));
  EXPECT_GT(click.x, v.dims.x / 2.0) << "a left-sided lesion must appear on the screen's right";

  glm::dvec3 picked = sliceToVoxel(axial, v.dims, click.x, click.y, std::round(voxel.z));
  glm::dvec3 mm = voxelToPatientMm(v, picked);
  EXPECT_NEAR(mm.x, lesion.centreMm.x, v.spacingMm.x);
  EXPECT_NEAR(mm.y, lesion.centreMm.y, v.spacingMm.y);
  EXPECT_NEAR(mm.z, lesion.centreMm.z, v.spacingMm.z);
  EXPECT_NEAR(sampleValue(v, picked), lesion.hu, 1.0);
  // World (relative to the centre, as the 3D view uses) differs from patient by the centre.
  glm::dvec3 centreMm = voxelToPatientMm(v, (glm::dvec3(v.dims) - 1.0) * 0.5);
  glm::dvec3 world = voxelToWorldMm(v, picked);
  EXPECT_NEAR(glm::distance(world + centreMm, mm), 0.0, 1e-9);
}

TEST(SliceImage, AppliesWindowAndScreenOrder) {
  Volume v;
  v.dims = {3, 2, 1};
  v.intercept = -1000;
  v.voxels = {0, 1000, 2000, 1040, 0, 0};  // HU: -1000, 0, 1000 / 40, -1000, -1000
  auto axial = sliceAxes(v.direction, Orientation::Axial);
  Image img = renderSlice(v, axial, 0, {80, 40}, Interp::Linear);
  ASSERT_EQ(img.width, 3);
  ASSERT_EQ(img.height, 2);
  EXPECT_EQ(img.pixel(0, 0)[0], 0);
  EXPECT_EQ(img.pixel(1, 0)[0], 0);    // 0 HU is the bottom of the brain window
  EXPECT_EQ(img.pixel(2, 0)[0], 255);  // bone
  EXPECT_EQ(img.pixel(0, 1)[0], 128);  // 40 HU: mid-grey
}
