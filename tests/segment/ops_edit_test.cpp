// Paint and erase in mm on anisotropic voxels, and undo/redo by label patches.
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ops_fixtures.h"
#include "voxray/io/segment_edit.h"

namespace voxray {
namespace {

using test::errorOf;
using ::testing::HasSubstr;

Segmentation twoSegments(glm::ivec3 dims, glm::dvec3 spacing) {
  Segmentation s;
  s.grid.dims = dims;
  s.grid.spacingMm = spacing;
  s.labels.assign(s.grid.voxelCount(), 0);
  Segment a, b;
  a.label = 1;
  a.name = "Liver";
  b.label = 2;
  b.name = "Tumour";
  s.segments = {a, b};
  return s;
}

size_t countLabel(const Segmentation& s, uint8_t label) {
  return size_t(std::count(s.labels.begin(), s.labels.end(), label));
}

TEST(SegmentPaint, ASphereOf10MmOnAnisotropicVoxelsHasTheVolumeOfItsSlices) {
  // 0.5 x 0.5 x 3 mm voxels: the ball meets 7 slices (z = 0, +-3, +-6, +-9 mm), whose discs
  // hold pi (100 - z²) mm² each: 3 mm x pi x 448 = 4222.3 mm³ (0.8 % above 4/3 pi 10³: the
  // sphere sampled at 3 mm). The in-plane count of each disc is within 1 % of its area at
  // 0.5 mm pixels on discs of 4.4 to 10 mm radius.
  Segmentation s = twoSegments({60, 60, 11}, {0.5, 0.5, 3.0});
  const LabelPatch p = paintSphere(s, {30, 30, 5}, 10.0, 1);
  const double volume = double(countLabel(s, 1)) * 0.75;
  EXPECT_NEAR(volume / (3.0 * M_PI * 448.0), 1.0, 0.01);
  EXPECT_NEAR(volume / (4.0 / 3.0 * M_PI * 1000.0), 1.0, 0.02);
  // Exactly the voxel centres within 10 mm.
  for (int z = 0; z < 11; ++z)
    for (int y = 0; y < 60; ++y)
      for (int x = 0; x < 60; ++x)
        ASSERT_EQ(s.labels[s.grid.index(x, y, z)] == 1,
                  test::mm(s.grid.spacingMm, {x, y, z}, {30, 30, 5}) <= 10.0);
  EXPECT_EQ(p.lo, glm::ivec3(10, 10, 2));
  EXPECT_EQ(p.hi, glm::ivec3(51, 51, 9));
}

TEST(SegmentPaint, ADiscStaysInItsSliceWithItsAreaInMm2) {
  Segmentation s = twoSegments({60, 60, 11}, {0.5, 0.5, 3.0});
  paintDisc(s, 2, {30.2, 29.7, 5.4}, 8.0, 2);
  size_t inSlice = 0;
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 60; ++x) inSlice += s.labels[s.grid.index(x, y, 5)] == 2;
  EXPECT_EQ(inSlice, countLabel(s, 2));
  // Exactly the pixel centres within 8 mm of the centre (30.2, 29.7) in that slice.
  for (int y = 0; y < 60; ++y)
    for (int x = 0; x < 60; ++x) {
      const double dx = (x - 30.2) * 0.5, dy = (y - 29.7) * 0.5;
      ASSERT_EQ(s.labels[s.grid.index(x, y, 5)] == 2, dx * dx + dy * dy <= 64.0) << x << "," << y;
    }
  // Its area: within 3 % of pi 64 mm² (804 pixels of 0.25 mm²): the lattice count of a disc
  // of radius 16 pixels strays from its area by up to about 20 pixels (Gauss's circle problem).
  EXPECT_NEAR(double(inSlice) * 0.25 / (M_PI * 64.0), 1.0, 0.03);
  // Across the slices (axis j): a disc in the plane y = 30 reaches 2 slices each way (6 mm).
  Segmentation t = twoSegments({60, 60, 11}, {0.5, 0.5, 3.0});
  paintDisc(t, 1, {30, 30, 5}, 8.0, 1);
  EXPECT_EQ(t.labels[t.grid.index(30, 30, 7)], 1);
  EXPECT_EQ(t.labels[t.grid.index(30, 30, 8)], 0);
  EXPECT_EQ(t.labels[t.grid.index(30, 31, 5)], 0);
}

TEST(SegmentPaint, OtherSegmentsAreKeptUnlessThePolicyOverwritesThem) {
  Segmentation s = twoSegments({20, 20, 20}, {1, 1, 1});
  paintSphere(s, {10, 10, 10}, 3.0, 2);
  const size_t tumour = countLabel(s, 2);
  paintSphere(s, {10, 10, 10}, 5.0, 1);
  EXPECT_EQ(countLabel(s, 2), tumour);
  paintSphere(s, {10, 10, 10}, 5.0, 1, EditPolicy{true});
  EXPECT_EQ(countLabel(s, 2), 0u);
  eraseSphere(s, {10, 10, 10}, 2.0, 2);  // erasing another label changes nothing
  EXPECT_EQ(s.labels[s.grid.index(10, 10, 10)], 1);
  eraseSphere(s, {10, 10, 10}, 2.0, 1);
  EXPECT_EQ(s.labels[s.grid.index(10, 10, 10)], 0);
  EXPECT_EQ(s.labels[s.grid.index(10, 10, 13)], 1);
}

TEST(SegmentUndo, SwappingThePatchesBackRestoresTheLabelsByteForByteAndRedoes) {
  Segmentation s = twoSegments({40, 30, 12}, {0.7, 0.7, 2.5});
  std::mt19937 random(7);
  for (auto& l : s.labels) l = random() % 7 == 0 ? 2 : 0;
  const auto before = s.labels;
  std::vector<LabelPatch> patches;
  patches.push_back(paintSphere(s, {10, 10, 5}, 6.0, 1));
  patches.push_back(paintDisc(s, 0, {12, 15, 6}, 5.0, 2, EditPolicy{true}));
  patches.push_back(eraseSphere(s, {11, 12, 5}, 3.0, 0));
  Mask m(s.labels.size(), 0);
  for (size_t i = 0; i < m.size(); i += 3) m[i] = 1;
  patches.push_back(setMask(s, 1, m, EditPolicy{true}));
  const auto after = s.labels;
  ASSERT_NE(after, before);
  for (auto p = patches.rbegin(); p != patches.rend(); ++p) swapPatch(s, *p);
  EXPECT_EQ(s.labels, before);
  for (auto& p : patches) swapPatch(s, p);
  EXPECT_EQ(s.labels, after);
}

TEST(SegmentPaint, AnEditThatChangesNothingGivesAnEmptyPatch) {
  Segmentation s = twoSegments({10, 10, 10}, {1, 1, 1});
  EXPECT_TRUE(eraseSphere(s, {5, 5, 5}, 2.0, 1).empty());
  EXPECT_TRUE(paintSphere(s, {50, 50, 50}, 2.0, 1).empty());  // wholly outside
}

TEST(SegmentPaint, BadLabelsRadiiAndMasksAreRefusedSayingWhatToDo) {
  Segmentation s = twoSegments({10, 10, 10}, {1, 1, 1});
  EXPECT_THAT(errorOf([&] {
                paintSphere(s, {5, 5, 5}, 2.0, 3);
              }),
              HasSubstr("There is no segment with label 3: add the segment before painting it."));
  EXPECT_THAT(errorOf([&] {
                paintSphere(s, {5, 5, 5}, 0.0, 1);
              }),
              HasSubstr("A brush radius of 0.000000 mm: give a radius from above 0 to 500 mm."));
  EXPECT_THAT(errorOf([&] {
                paintDisc(s, 3, {5, 5, 5}, 1.0, 1);
              }),
              HasSubstr("A slice's axis is 0 (i), 1 (j) or 2 (k)."));
  EXPECT_THAT(
      errorOf([&] { setMask(s, 1, Mask(5, 1)); }),
      HasSubstr("The mask has 5 voxels, the label map 1000: both must lie on the same grid."));
}

}  // namespace
}  // namespace voxray
