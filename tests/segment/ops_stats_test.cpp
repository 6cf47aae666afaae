// Segment statistics: voxels, volume, HU, and their CSV and JSON text.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ops_fixtures.h"
#include "voxray/io/segment_stats.h"

namespace voxray {
namespace {

using test::errorOf;
using ::testing::HasSubstr;

// Stored x * 10 along x with HU = stored - 20: HU -20, -10, 0, ..., 70 on 0.5 x 0.5 x 2 mm.
struct Case {
  Volume v;
  Segmentation s;
};
Case statsCase() {
  Case c;
  c.v = test::makeVolume({10, 2, 2}, {0.5, 0.5, 2.0},
                         [](int x, int, int) { return int16_t(10 * x); });
  c.v.intercept = -20.0;
  c.s = emptySegmentation(c.v);
  Segment a, b;
  a.label = 1;
  a.name = "Bone, \"cortical\"";
  b.label = 4;
  b.name = "Empty";
  c.s.segments = {a, b};
  // Label 1 at x = 1, 2, 3, 6 of row (y 0, z 0): HU -10, 0, 10, 40.
  for (int x : {1, 2, 3, 6}) c.s.labels[c.v.index(x, 0, 0)] = 1;
  return c;
}

TEST(SegmentStats, CountVolumeAndHuMomentsOfFourKnownVoxels) {
  const Case c = statsCase();
  const SegmentStats s = segmentStats(c.s, c.v, 1);
  EXPECT_EQ(s.voxels, 4u);
  EXPECT_DOUBLE_EQ(s.volumeMm3, 2.0);  // 4 x 0.5 mm³
  EXPECT_DOUBLE_EQ(s.volumeMl, 0.002);
  EXPECT_DOUBLE_EQ(*s.mean, 10.0);
  EXPECT_NEAR(*s.sd, std::sqrt(350.0), 1e-12);  // population SD: (400+100+0+900)/4
  EXPECT_DOUBLE_EQ(*s.min, -10.0);
  EXPECT_DOUBLE_EQ(*s.max, 40.0);
  EXPECT_DOUBLE_EQ(*s.median, 5.0);  // mean of the middle two, 0 and 10
  EXPECT_FALSE(s.surfaceMm2);
  const SegmentStats empty = segmentStats(c.s, c.v, 4);
  EXPECT_EQ(empty.voxels, 0u);
  EXPECT_FALSE(empty.mean);
  EXPECT_FALSE(empty.median);
}

TEST(SegmentStats, JsonAndCsvCarryTheSameNumbersAndQuoteNames) {
  const Case c = statsCase();
  const auto all = allSegmentStats(c.s, c.v);
  const auto j = nlohmann::json::parse(statsJson(all));
  ASSERT_EQ(j["segments"].size(), 2u);
  EXPECT_EQ(j["segments"][0]["name"], "Bone, \"cortical\"");
  EXPECT_EQ(j["segments"][0]["voxels"], 4);
  EXPECT_DOUBLE_EQ(j["segments"][0]["median"].get<double>(), 5.0);
  EXPECT_TRUE(j["segments"][0]["surface_mm2"].is_null());
  EXPECT_TRUE(j["segments"][1]["mean"].is_null());
  EXPECT_TRUE(j["segments"][0]["suv_peak"].is_null());  // a CT: no SUV
  EXPECT_FALSE(j["segments"][0].contains("suv_peak_note"));
  EXPECT_EQ(statsCsv(all),
            "label,name,voxels,volume_mm3,volume_ml,unit,mean,sd,min,max,median,surface_mm2,"
            "suv_peak\n"
            "1,\"Bone, \"\"cortical\"\"\",4,2,0.002,HU,10,18.7083,-10,40,5,,\n"
            "4,Empty,0,0,0,HU,,,,,,,\n");
}

TEST(SegmentStats, ALabelMapOnAnotherGridIsRefusedNamingBothGrids) {
  Case c = statsCase();
  c.s.grid.spacingMm.z = 2.5;
  EXPECT_THAT(errorOf([&] { segmentStats(c.s, c.v, 1); }),
              HasSubstr("The label map's geometry (10x2x2 voxels of 0.5 x 0.5 x 2.5 mm"));
}

}  // namespace
}  // namespace voxray
