#include <gtest/gtest.h>

#include "crosshair_model.h"

using namespace voxray;

namespace {
const glm::dmat3 kIdentity(1.0);
}

TEST(Crosshair, ClickInAxialMovesCoronalAndSagittal) {
  CrosshairModel m;
  m.setDims({100, 80, 60});
  auto axial = sliceAxes(kIdentity, Orientation::Axial);
  auto coronal = sliceAxes(kIdentity, Orientation::Coronal);
  auto sagittal = sliceAxes(kIdentity, Orientation::Sagittal);
  int axialBefore = m.sliceOf(axial);
  int notified = 0;
  m.changed.connect([&] { ++notified; });
  m.clickInView(axial, 20.5, 70.5);  // the centre of slice pixel (20, 70)
  EXPECT_EQ(notified, 1);
  EXPECT_EQ(m.sliceOf(sagittal), 20);  // x
  EXPECT_EQ(m.sliceOf(coronal), 70);   // y
  EXPECT_EQ(m.sliceOf(axial), axialBefore);
}

TEST(Crosshair, ClickInCoronalKeepsYAndFlipsZ) {
  CrosshairModel m;
  m.setDims({100, 80, 60});
  auto coronal = sliceAxes(kIdentity, Orientation::Coronal);
  m.clickInView(coronal, 10.5, 0.5);  // top row of the coronal view is the highest z
  EXPECT_EQ(m.voxel(), glm::ivec3(10, 40, 59));
}

TEST(Crosshair, ScrollMovesAlongTheNormalAndClamps) {
  CrosshairModel m;
  m.setDims({10, 10, 10});
  auto axial = sliceAxes(kIdentity, Orientation::Axial);
  m.scrollView(axial, 3);
  EXPECT_EQ(m.voxel(), glm::ivec3(5, 5, 8));
  m.scrollView(axial, 100);
  EXPECT_EQ(m.voxel().z, 9);
  m.scrollView(axial, -100);
  EXPECT_EQ(m.voxel().z, 0);
}
