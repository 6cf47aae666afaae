// Thresholds, the seeded region, islands and holes.
#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ops_fixtures.h"
#include "segment_itk.h"
#include "voxray/io/segment_ops.h"

namespace voxray {
namespace {

using test::count;
using test::errorOf;
using test::makeVolume;
using ::testing::HasSubstr;

TEST(SegmentThreshold, TakesTheRangeInHuThroughSlopeAndInterceptWithBothEndsIncluded) {
  // Stored 0..9 along x with HU = stored * 2 - 1024: HU -1024, -1022, ..., -1006.
  Volume v = makeVolume({10, 1, 1}, {1, 1, 1}, [](int x, int, int) { return int16_t(x); });
  v.slope = 2.0;
  v.intercept = -1024.0;
  const Mask m = thresholdMask(v, {-1020.0, -1013.0});  // stored 2 (HU -1020) to 5 (-1014)
  EXPECT_EQ(m, (Mask{0, 0, 1, 1, 1, 1, 0, 0, 0, 0}));
  const Mask none = thresholdMask(v, {-1019.5, -1018.5});  // between stored values
  EXPECT_EQ(count(none), 0u);
}

TEST(SegmentThreshold, AnEmptyOrUnnumberedRangeSaysWhatToGive) {
  const Volume v = makeVolume({4, 4, 4}, {1, 1, 1}, [](int, int, int) { return int16_t(0); });
  EXPECT_THAT(errorOf([&] {
                thresholdMask(v, {300.0, 100.0});
              }),
              HasSubstr("is empty: give the lower value first (LO,HI)"));
  EXPECT_THAT(errorOf([&] {
                thresholdMask(v, {NAN, 100.0});
              }),
              HasSubstr("needs two numbers (LO,HI in HU)"));
}

TEST(SegmentThreshold, TheSlicePreviewIsTheVolumesThresholdOfThatSlice) {
  const Volume v = makeVolume({7, 5, 4}, {0.5, 0.7, 2.0}, [](int x, int y, int z) {
    return int16_t((x * 7 + y * 3 + z * 5) % 11);
  });
  const HuRange r{3.0, 7.0};
  const Mask all = thresholdMask(v, r);
  for (int axis = 0; axis < 3; ++axis) {
    const int u = axis == 0 ? 1 : 0, w = axis == 2 ? 1 : 2;
    for (int slice = 0; slice < v.dims[axis]; ++slice) {
      const Mask m = thresholdSlice(v, axis, slice, r);
      ASSERT_EQ(m.size(), size_t(v.dims[u] * v.dims[w]));
      glm::ivec3 p(0);
      p[axis] = slice;
      for (p[w] = 0; p[w] < v.dims[w]; ++p[w])
        for (p[u] = 0; p[u] < v.dims[u]; ++p[u])
          ASSERT_EQ(m[size_t(p[w] * v.dims[u] + p[u])], all[v.index(p.x, p.y, p.z)]);
    }
  }
  EXPECT_THAT(errorOf([&] { thresholdSlice(v, 2, 4, r); }),
              HasSubstr("Slice 4 is outside the volume (0 to 3 along k)"));
}

TEST(SegmentSeededRegion, ASphereOf40MmOn07MmVoxelsHasItsAnalyticVolume) {
  // Voxel centres inside r = 40 mm at 0.7 mm spacing: the count's error against 4/3 pi r^3 is
  // a surface effect of order (h / r)^2, well under 0.5 % at r / h = 57.
  const double r = 40.0, h = 0.7;
  const int n = 2 * int(std::ceil(r / h)) + 5;
  const glm::dvec3 c(n / 2);
  const Volume v = makeVolume({n, n, n}, {h, h, h}, [&](int x, int y, int z) {
    const glm::dvec3 d = (glm::dvec3(x, y, z) - c) * h;
    return int16_t(glm::dot(d, d) <= r * r ? 80 : -1000);
  });
  const Mask m = seededRegion(v, {0.0, 200.0}, glm::ivec3(c), Connectivity::Faces6);
  const double volume = double(count(m)) * h * h * h;
  const double exact = 4.0 / 3.0 * M_PI * r * r * r;
  EXPECT_NEAR(volume / exact, 1.0, 0.005);
  EXPECT_EQ(m, thresholdMask(v, {0.0, 200.0}));  // one connected body: the seed reaches all
}

// Two 3x3x3 cubes that touch only at one corner: (4,4,4) and (5,5,5).
Volume cornerTouchingCubes() {
  return makeVolume({10, 10, 10}, {1, 1, 1}, [](int x, int y, int z) {
    const auto in = [&](int lo) {
      return x >= lo && x < lo + 3 && y >= lo && y < lo + 3 && z >= lo && z < lo + 3;
    };
    return int16_t(in(2) || in(5) ? 500 : 0);
  });
}

TEST(SegmentSeededRegion, SixConnectivityStopsAtACornerThat26Crosses) {
  const Volume v = cornerTouchingCubes();
  EXPECT_EQ(count(seededRegion(v, {300, 700}, {2, 2, 2}, Connectivity::Faces6)), 27u);
  EXPECT_EQ(count(seededRegion(v, {300, 700}, {2, 2, 2}, Connectivity::Full26)), 54u);
  EXPECT_EQ(count(seededRegion(v, {300, 700}, {7, 7, 7}, Connectivity::Faces6)), 27u);
}

TEST(SegmentSeededRegion, ASeedOutsideTheVolumeOrTheRangeIsRefusedSayingWhy) {
  const Volume v = cornerTouchingCubes();
  EXPECT_THAT(errorOf([&] {
                seededRegion(v, {300, 700}, {10, 2, 2});
              }),
              HasSubstr("The seed 10:2:2 is outside the volume (0:0:0 to 9:9:9)"));
  EXPECT_THAT(errorOf([&] {
                seededRegion(v, {300, 700}, {-1, 2, 2});
              }),
              HasSubstr("outside the volume"));
  EXPECT_THAT(errorOf([&] {
                seededRegion(v, {300, 700}, {0, 0, 0});
              }),
              HasSubstr("The seed 0:0:0 has 0.000000 HU, outside the threshold range 300.000000 "
                        "to 700.000000: put it on the structure or widen the range."));
  EXPECT_THAT(errorOf([&] { seededRegion(v, {700, 300}, {2, 2, 2}); }), HasSubstr("is empty"));
}

// Islands of 1, 8 and 27 voxels on 1 x 1 x 2 mm voxels (2, 16 and 54 mm³).
struct IslandMask {
  VoxelGrid g;
  Mask m;
};
IslandMask islands() {
  IslandMask im;
  im.g.dims = {12, 12, 12};
  im.g.spacingMm = {1, 1, 2};
  im.m.assign(im.g.voxelCount(), 0);
  const auto cube = [&](glm::ivec3 lo, int n) {
    for (int z = lo.z; z < lo.z + n; ++z)
      for (int y = lo.y; y < lo.y + n; ++y)
        for (int x = lo.x; x < lo.x + n; ++x) im.m[im.g.index(x, y, z)] = 1;
  };
  cube({1, 1, 1}, 1);
  cube({4, 4, 4}, 2);
  cube({8, 8, 8}, 3);
  return im;
}

TEST(SegmentIslands, KeepLargestKeepClickedAndRemoveSmallerThanMm3) {
  {
    auto im = islands();
    keepLargestIsland(im.g, im.m);
    EXPECT_EQ(count(im.m), 27u);
    EXPECT_EQ(im.m[im.g.index(9, 9, 9)], 1);
  }
  {
    auto im = islands();
    keepIslandAt(im.g, im.m, {5, 5, 5});
    EXPECT_EQ(count(im.m), 8u);
    EXPECT_EQ(im.m[im.g.index(4, 4, 4)], 1);
  }
  {
    auto im = islands();
    removeSmallIslands(im.g, im.m, 16.0);  // keeps 16 mm³ (8 voxels of 2 mm³) and 54 mm³
    EXPECT_EQ(count(im.m), 35u);
    removeSmallIslands(im.g, im.m, 16.1);
    EXPECT_EQ(count(im.m), 27u);
  }
  auto im = islands();
  EXPECT_THAT(errorOf([&] {
                keepIslandAt(im.g, im.m, {0, 0, 0});
              }),
              HasSubstr("The voxel 0:0:0 is not in the segment: click on the island to keep."));
  EXPECT_THAT(errorOf([&] {
                keepIslandAt(im.g, im.m, {0, 12, 0});
              }),
              HasSubstr("The voxel 0:12:0 is outside the volume"));
  EXPECT_THAT(errorOf([&] { removeSmallIslands(im.g, im.m, -1.0); }),
              HasSubstr("must be 0 mm³ or more"));
}

TEST(SegmentIslands, DiagonalNeighboursAreOneIslandWith26AndTwoWith6) {
  auto im = islands();
  im.m.assign(im.g.voxelCount(), 0);
  im.m[im.g.index(3, 3, 3)] = im.m[im.g.index(4, 4, 4)] = im.m[im.g.index(5, 5, 5)] = 1;
  auto six = im.m;
  keepLargestIsland(im.g, six, Connectivity::Faces6);
  EXPECT_EQ(count(six), 1u);
  keepLargestIsland(im.g, im.m, Connectivity::Full26);
  EXPECT_EQ(count(im.m), 3u);
}

TEST(SegmentHoles, AHollowSphereIsFilledToTheSolidBallAndAnOpenCavityIsNot) {
  VoxelGrid g;
  g.dims = {40, 40, 40};
  g.spacingMm = {1, 1, 1};
  const glm::dvec3 c(20.0);
  Mask shell(g.voxelCount()), ball(g.voxelCount());
  for (int z = 0; z < 40; ++z)
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) {
        const double r = glm::length(glm::dvec3(x, y, z) - c);
        shell[g.index(x, y, z)] = r <= 15.0 && r > 11.0;
        ball[g.index(x, y, z)] = r <= 15.0;
      }
  Mask filled = shell;
  fillHoles(g, filled);
  EXPECT_EQ(filled, ball);
#ifdef VOXRAY_SEGMENT_WITH_ITK
  // ITK's BinaryFillholeImageFilter agrees (the bench compares their times).
  itk_ops::Block block{g.dims, g.spacingMm, shell};
  itk_ops::fillHoles(block);
  EXPECT_EQ(block.voxels, ball);
#endif
  EXPECT_GT(count(ball) - count(shell), 5000u);  // the cavity: 4/3 pi 11^3 = 5575 mm³

  // A tunnel along +x from the cavity to the outside: the cavity is no hole any more.
  Mask open = shell;
  for (int x = 20; x < 40; ++x) open[g.index(x, 20, 20)] = 0;
  Mask result = open;
  fillHoles(g, result);
  EXPECT_EQ(result, open);
}

TEST(SegmentLogical, AddSubtractIntersectWithAnotherSegmentOrAMask) {
  Segmentation s;
  s.grid.dims = {4, 1, 1};
  s.labels = {1, 1, 2, 0};
  Segment a, b;
  a.label = 1;
  b.label = 2;
  s.segments = {a, b};
  EXPECT_EQ(logical(s, 1, 2, LogicalOp::Add), (Mask{1, 1, 1, 0}));
  EXPECT_EQ(logical(s, 1, 2, LogicalOp::Subtract), (Mask{1, 1, 0, 0}));
  EXPECT_EQ(logical(s, 1, 2, LogicalOp::Intersect), (Mask{0, 0, 0, 0}));
  const Mask other{0, 1, 1, 1};
  EXPECT_EQ(logical(s, 1, other, LogicalOp::Add), (Mask{1, 1, 1, 1}));
  EXPECT_EQ(logical(s, 1, other, LogicalOp::Subtract), (Mask{1, 0, 0, 0}));
  EXPECT_EQ(logical(s, 1, other, LogicalOp::Intersect), (Mask{0, 1, 0, 0}));
  EXPECT_THAT(errorOf([&] { logical(s, 1, 3, LogicalOp::Add); }),
              HasSubstr("There is no segment with label 3."));
  EXPECT_THAT(errorOf([&] {
                logical(s, 1, Mask{1, 1}, LogicalOp::Add);
              }),
              HasSubstr("both must lie on the same grid"));
}

}  // namespace
}  // namespace voxray
