// The stored-value histogram a transfer-function editor draws over (issue 35): exact counts,
// across the chunks the parallel count splits a volume into, and nothing once cancelled.
#include <gtest/gtest.h>

#include "voxray/io/histogram.h"
#include "voxray/io/volume.h"

namespace voxray {
namespace {

// DIMS voxels of 0, with N_AIR of -1000 at the start and one of 3000 at the very end.
Volume sample(glm::ivec3 dims, size_t nAir) {
  Volume v;
  v.dims = dims;
  v.voxels.assign(v.voxelCount(), 0);
  for (size_t i = 0; i < nAir; ++i) v.voxels[i] = -1000;
  v.voxels.back() = 3000;
  return v;
}

TEST(Histogram, CountsEveryStoredValueExactly) {
  const Volume v = sample({4, 4, 4}, 10);
  const StoredHistogram h = storedHistogram(v);
  EXPECT_EQ(h.min, -1000);
  EXPECT_EQ(h.max, 3000);
  ASSERT_EQ(h.counts.size(), 4001u);
  EXPECT_EQ(h.total, 64u);
  EXPECT_EQ(h.counts[0], 10u);
  EXPECT_EQ(h.counts[1000], 53u);
  EXPECT_EQ(h.counts[4000], 1u);
  EXPECT_EQ(h.countIn(-2000.0, -500.0), 10u);
  EXPECT_EQ(h.countIn(-0.5, 0.5), 53u);
  EXPECT_EQ(h.countIn(0.5, 2999.5), 0u);
  EXPECT_EQ(h.countIn(-32768.0, 32767.0), 64u);
}

TEST(Histogram, ChunksOfAVolumeLargerThanOneAddUp) {
  // 160 x 160 x 400 = 10.24 M voxels: three chunks of 4 Mi, the last one partial.
  const Volume v = sample({160, 160, 400}, 5'000'000);
  const StoredHistogram h = storedHistogram(v);
  EXPECT_EQ(h.total, 10'240'000u);
  EXPECT_EQ(h.counts.front(), 5'000'000u);
  EXPECT_EQ(h.counts[1000], 10'240'000u - 5'000'001u);
  EXPECT_EQ(h.counts.back(), 1u);
}

TEST(Histogram, ACancelledCountIsEmpty) {
  const Volume v = sample({64, 64, 64}, 100);
  std::atomic<bool> cancel{true};
  EXPECT_TRUE(storedHistogram(v, &cancel).empty());
  EXPECT_TRUE(storedHistogram(Volume{}).empty());
}

}  // namespace
}  // namespace voxray
