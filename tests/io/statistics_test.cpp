// The one median and quantile every layer uses: values, even and odd counts, the empty case.
#include <gtest/gtest.h>

#include "voxray/io/statistics.h"

namespace voxray {
namespace {

TEST(Statistics, MedianIsTheMiddleOrTheMeanOfTheTwoMiddleValues) {
  EXPECT_DOUBLE_EQ(median({5.0, 1.0, 3.0}), 3.0);
  EXPECT_DOUBLE_EQ(median({4.0, 1.0, 3.0, 10.0}), 3.5);
  EXPECT_DOUBLE_EQ(median({7.0}), 7.0);
  EXPECT_DOUBLE_EQ(median({}), 0.0);
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
