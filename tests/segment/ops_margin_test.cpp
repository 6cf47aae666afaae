// Margins: an exact Euclidean distance in mm on anisotropic voxels.
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ops_fixtures.h"
#include "voxray/io/segment_ops.h"

namespace voxray {
namespace {

using test::count;
using test::errorOf;
using ::testing::HasSubstr;

VoxelGrid grid(glm::ivec3 dims, glm::dvec3 spacing) {
  VoxelGrid g;
  g.dims = dims;
  g.spacingMm = spacing;
  return g;
}

// The margin by brute force: for each voxel the nearest voxel of the other kind.
Mask bruteForce(const VoxelGrid& g, const Mask& m, double mm) {
  Mask out(m.size());
  for (int z = 0; z < g.dims.z; ++z)
    for (int y = 0; y < g.dims.y; ++y)
      for (int x = 0; x < g.dims.x; ++x) {
        const size_t i = g.index(x, y, z);
        const bool grow = mm > 0;
        if (grow ? m[i] : !m[i]) {
          out[i] = m[i];
          continue;
        }
        // Growing: is a mask voxel within mm? Shrinking: is a background voxel within |mm|?
        bool near = false;
        for (int c = 0; c < g.dims.z && !near; ++c)
          for (int b = 0; b < g.dims.y && !near; ++b)
            for (int a = 0; a < g.dims.x && !near; ++a)
              near = (m[g.index(a, b, c)] != 0) == grow &&
                     test::mm(g.spacingMm, {x, y, z}, {a, b, c}) <= std::abs(mm) + 1e-9;
        out[i] = grow ? near : !near;
      }
  return out;
}

TEST(SegmentMargin, TwoMillimetresOnHalfByHalfByThreeMmVoxelsIsExactAtEveryVoxelCentre) {
  const VoxelGrid g = grid({24, 24, 9}, {0.5, 0.5, 3.0});
  Mask m(g.voxelCount(), 0);
  m[g.index(12, 12, 4)] = 1;
  Mask grown = m;
  applyMargin(g, grown, 2.0);
  // 4 voxels (2 mm) each way in plane; the next slice is 3 mm away, so none across.
  EXPECT_EQ(grown[g.index(16, 12, 4)], 1);
  EXPECT_EQ(grown[g.index(17, 12, 4)], 0);
  EXPECT_EQ(grown[g.index(12, 12, 5)], 0);
  EXPECT_EQ(grown, bruteForce(g, m, 2.0));
  // The disc of radius 4 voxels: 49 voxel centres within it.
  EXPECT_EQ(count(grown), 49u);
}

// Small margins take a window of a few voxels along an axis, larger ones the parabola
// envelope (segment_margin.cpp): these margins and spacings go through both, along y and z.
TEST(SegmentMargin, GrowAndShrinkOfRandomBlobsEqualTheBruteForceDistances) {
  for (const glm::dvec3 spacing : {glm::dvec3(0.5, 0.5, 3.0), glm::dvec3(0.7, 0.6, 0.4)}) {
    const VoxelGrid g = grid({20, 18, 9}, spacing);
    std::mt19937 random(34);
    Mask m(g.voxelCount(), 0);
    for (int n = 0; n < 40; ++n) {
      const glm::ivec3 p(random() % 20, random() % 18, random() % 9);
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -3; dx <= 3; ++dx) {
          const glm::ivec3 q = glm::clamp(p + glm::ivec3(dx, dy, 0), glm::ivec3(0), g.dims - 1);
          m[g.index(q.x, q.y, q.z)] = 1;
        }
    }
    for (double mm : {2.0, 3.0, 1.2, -1.0, -2.0, -3.5}) {
      Mask out = m;
      applyMargin(g, out, mm);
      EXPECT_EQ(out, bruteForce(g, m, mm)) << mm << " mm on " << spacing.z << " mm slices";
    }
  }
}

TEST(SegmentMargin, ABallGrownBy2MmReachesRadiusPlus2WithinHalfAVoxel) {
  // Ball of 10 mm on 0.5 x 0.5 x 3 mm voxels grown by 2 mm: along x the last voxel centre in
  // the mask lies within half a voxel (0.25 mm) of 12 mm from the centre. Along z the ball's
  // last slice is at 9 mm and the next (12 mm) is 3 mm from it, beyond the margin: the margin
  // is a distance from the voxels, not a voxel step, so z stays at 9 mm.
  const VoxelGrid g = grid({80, 80, 20}, {0.5, 0.5, 3.0});
  const glm::dvec3 c(40, 40, 10);
  Mask m(g.voxelCount(), 0);
  for (int z = 0; z < 20; ++z)
    for (int y = 0; y < 80; ++y)
      for (int x = 0; x < 80; ++x)
        m[g.index(x, y, z)] = glm::length((glm::dvec3(x, y, z) - c) * g.spacingMm) <= 10.0;
  applyMargin(g, m, 2.0);
  int xmax = 40, zmax = 10;
  while (m[g.index(xmax + 1, 40, 10)]) ++xmax;
  while (m[g.index(40, 40, zmax + 1)]) ++zmax;
  EXPECT_NEAR((xmax - 40) * 0.5, 12.0, 0.25);
  EXPECT_EQ(zmax - 10, 3);
}

TEST(SegmentMargin, ShrinkingDoesNotEatFromTheVolumesBorder) {
  const VoxelGrid g = grid({6, 6, 6}, {1, 1, 1});
  Mask m(g.voxelCount(), 1);
  applyMargin(g, m, -2.0);
  EXPECT_EQ(count(m), g.voxelCount());
}

TEST(SegmentMargin, AMarginBeyond500MmIsRefused) {
  const VoxelGrid g = grid({4, 4, 4}, {1, 1, 1});
  Mask m(g.voxelCount(), 1);
  EXPECT_THAT(errorOf([&] { applyMargin(g, m, 600.0); }),
              HasSubstr("give a distance from -500 to 500 mm (negative shrinks)"));
}

TEST(SegmentSmoothing, MedianRemovesASpeckAndClosingFillsAGapNarrowerThanItsKernel) {
  const VoxelGrid g = grid({20, 20, 20}, {1, 1, 1});
  Mask m(g.voxelCount(), 0);
  for (int z = 5; z < 15; ++z)
    for (int y = 5; y < 15; ++y)
      for (int x = 5; x < 15; ++x) m[g.index(x, y, z)] = x != 10;  // a 1 mm gap at x = 10
  m[g.index(1, 1, 1)] = 1;                                         // a speck
  Mask median = m;
  medianSmooth(g, median, 3.0);  // 3x3x3 vote
  EXPECT_EQ(median[g.index(1, 1, 1)], 0);
  Mask closed = m;
  closing(g, closed, 3.0);  // radius 1 voxel
  EXPECT_EQ(closed[g.index(10, 10, 10)], 1);
  EXPECT_EQ(closed[g.index(1, 1, 1)], 1);
  Mask opened = m;
  opening(g, opened, 3.0);
  EXPECT_EQ(opened[g.index(1, 1, 1)], 0);
  EXPECT_EQ(opened[g.index(7, 7, 7)], 1);
  EXPECT_THAT(errorOf([&] { medianSmooth(g, median, -1.0); }),
              HasSubstr("The median kernel of -1.000000 mm: give a size from 0 to 1000 mm."));
}

}  // namespace
}  // namespace voxray
