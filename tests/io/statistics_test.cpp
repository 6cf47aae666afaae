// The one median and quantile every layer uses: values, even and odd counts, the empty case.
#include <gtest/gtest.h>

#include "voxray/io/statistics.h"
#include "voxray/io/volume.h"

namespace voxray {
namespace {

TEST(Statistics, MedianIsTheMiddleOrTheMeanOfTheTwoMiddleValues) {
  EXPECT_DOUBLE_EQ(median({5.0, 1.0, 3.0}), 3.0);
  EXPECT_DOUBLE_EQ(median({4.0, 1.0, 3.0, 10.0}), 3.5);
  EXPECT_DOUBLE_EQ(median({7.0}), 7.0);
  EXPECT_DOUBLE_EQ(median({}), 0.0);
}

// storedRange's vectorised loop (issue 39 item 8): extremes at either end, at odd offsets
// past a vector's width, the int16 limits themselves, one voxel, and the empty volume.
TEST(Statistics, StoredRangeIsTheSmallestAndLargestValueWhereverTheyAre) {
  Volume v;
  v.dims = {37, 3, 1};  // 111 voxels: not a multiple of any vector width
  v.voxels.assign(v.voxelCount(), 7);
  EXPECT_EQ(storedRange(v).min, 7);
  EXPECT_EQ(storedRange(v).max, 7);
  v.voxels.front() = -1024;
  v.voxels.back() = 3071;
  EXPECT_EQ(storedRange(v).min, -1024);
  EXPECT_EQ(storedRange(v).max, 3071);
  v.voxels[53] = -32768;
  v.voxels[101] = 32767;
  EXPECT_EQ(storedRange(v).min, -32768);
  EXPECT_EQ(storedRange(v).max, 32767);
  Volume one;
  one.dims = {1, 1, 1};
  one.voxels.assign(1, -5);
  EXPECT_EQ(storedRange(one).min, -5);
  EXPECT_EQ(storedRange(one).max, -5);
  EXPECT_EQ(storedRange(Volume{}).min, 0);  // empty: {0, 0}
  EXPECT_EQ(storedRange(Volume{}).max, 0);
}

TEST(Statistics, QuantileIsTheNearestRankAndOneOfTheValues) {
  const std::vector<double> v = {50, 10, 40, 20, 30, 60, 70, 80, 90, 100};
  EXPECT_DOUBLE_EQ(quantile(v, 0.0), 10.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.5), 60.0);  // index 5 of 10: the upper middle value
  EXPECT_DOUBLE_EQ(quantile(v, 0.9), 100.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.89), 90.0);
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 100.0);
  EXPECT_DOUBLE_EQ(quantile(v, 2.0), 100.0);  // clamped to [0, 1]
  EXPECT_DOUBLE_EQ(quantile(v, -1.0), 10.0);
  EXPECT_DOUBLE_EQ(quantile({}, 0.5), 0.0);
}

}  // namespace
}  // namespace voxray
