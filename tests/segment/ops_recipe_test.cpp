// The recipe the CLI and the editor share, and the output dispatch.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "ops_fixtures.h"
#include "voxray/io/segment_output.h"
#include "voxray/io/segment_recipe.h"

namespace voxray {
namespace {

using test::count;
using test::errorOf;
using ::testing::HasSubstr;

// A 12 mm ball of 300 HU with a 4 mm cavity of 0 HU, and a 2-voxel speck of 300 HU apart.
Volume hollowBallAndSpeck() {
  return test::makeVolume({40, 40, 20}, {1, 1, 2}, [](int x, int y, int z) {
    const double r =
        glm::length((glm::dvec3(x, y, z) - glm::dvec3(20, 20, 10)) * glm::dvec3(1, 1, 2));
    if ((x == 2 || x == 3) && y == 2 && z == 2) return int16_t(300);
    return int16_t(r <= 12.0 && r > 4.0 ? 300 : 0);
  });
}

TEST(SegmentRecipe, ThresholdKeepLargestFillHolesThenMarginInThatOrder) {
  const Volume v = hollowBallAndSpeck();
  SegmentRecipe r;
  r.threshold = {200, 400};
  const Mask plain = runRecipe(v, r);
  r.keepLargest = true;
  const Mask largest = runRecipe(v, r);
  EXPECT_EQ(count(plain) - count(largest), 2u);  // the speck
  r.fillHoles = true;
  const Mask filled = runRecipe(v, r);
  EXPECT_GT(count(filled), count(largest));
  EXPECT_EQ(filled[v.index(20, 20, 10)], 1);
  r.marginMm = -1.0;
  Mask expected = filled;
  applyMargin(gridOf(v), expected, -1.0);
  EXPECT_EQ(runRecipe(v, r), expected);
  // A seed on the speck gives the speck alone.
  SegmentRecipe speck;
  speck.threshold = {200, 400};
  speck.seed = glm::ivec3(2, 2, 2);
  EXPECT_EQ(count(runRecipe(v, speck)), 2u);
}

TEST(SegmentRecipe, ASeedInMmIsItsNearestVoxelAndOutsideIsRefused) {
  const Volume v = hollowBallAndSpeck();  // origin (-100, -50, 20), spacing 1, 1, 2
  EXPECT_EQ(seedFromMm(v, {-80.2, -30.4, 40.9}), glm::ivec3(20, 20, 10));
  EXPECT_THAT(errorOf([&] {
                seedFromMm(v, {-80.0, -30.0, 0.0});
              }),
              HasSubstr("is outside the volume: give a point inside it."));
}

TEST(SegmentRecipe, TheSegmentationHasOneNamedSegmentWithTheMask) {
  const Volume v = hollowBallAndSpeck();
  SegmentRecipe r;
  r.threshold = {200, 400};
  r.name = "Skull";
  r.colour = {1.0f, 0.5f, 0.25f};
  const Segmentation s = segmentationFromRecipe(v, r);
  ASSERT_EQ(s.segments.size(), 1u);
  EXPECT_EQ(s.segments[0].name, "Skull");
  EXPECT_EQ(s.segments[0].label, 1);
  EXPECT_EQ(s.segments[0].colour, glm::vec3(1.0f, 0.5f, 0.25f));
  const Mask m = runRecipe(v, r);
  for (size_t i = 0; i < m.size(); ++i) ASSERT_EQ(s.labels[i], m[i]);
}

class SegmentOutput : public ::testing::Test {
 protected:
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("voxray_segment_output_" + std::to_string(::getpid()));
  void SetUp() override { std::filesystem::create_directories(dir); }
  void TearDown() override { std::filesystem::remove_all(dir); }
};

TEST_F(SegmentOutput, TheRawLabelDumpAndItsSidecarDescribeTheGrid) {
  const Volume v = hollowBallAndSpeck();
  SegmentRecipe r;
  r.threshold = {200, 400};
  r.name = "Skull";
  const Segmentation s = segmentationFromRecipe(v, r);
  const std::string path = (dir / "skull.labels.raw").string();
  writeSegmentationOutput(path, s, v, false);
  std::ifstream in(path, std::ios::binary);
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(bytes, s.labels);
  std::ifstream side(dir / "skull.labels.json");
  const auto j = nlohmann::json::parse(side);
  EXPECT_EQ(j["dims"], nlohmann::json({40, 40, 20}));
  EXPECT_EQ(j["spacing_mm"], nlohmann::json({1.0, 1.0, 2.0}));
  EXPECT_EQ(j["origin_lps_mm"], nlohmann::json({-100.0, -50.0, 20.0}));
  EXPECT_EQ(j["segments"][0]["name"], "Skull");
  EXPECT_EQ(j["segments"][0]["label"], 1);

  EXPECT_THAT(errorOf([&] { writeSegmentationOutput(path, s, v, false); }, Error::Kind::Output),
              HasSubstr("exists: give --force to replace it, or another name."));
  EXPECT_NO_THROW(writeSegmentationOutput(path, s, v, true));
}

TEST_F(SegmentOutput, FormatsNotInThisBuildAndUnknownNamesAreRefused) {
  const Volume v = hollowBallAndSpeck();
  const Segmentation s = emptySegmentation(v);
  for (const char* name : {"a.stl", "a.OBJ", "a.nii.gz", "a.seg.nrrd", "a.dcm"})
    EXPECT_THAT(errorOf([&] { writeSegmentationOutput((dir / name).string(), s, v, false); },
                        Error::Kind::Output),
                HasSubstr("files is not available in this build yet"))
        << name;
  EXPECT_THAT(errorOf([&] { writeSegmentationOutput((dir / "a.png").string(), s, v, false); }),
              HasSubstr("a.png: give an output ending in .stl, .obj, .ply"));
  Segmentation other = s;
  other.grid.originMm.x += 1.0;
  EXPECT_THAT(
      errorOf([&] { writeSegmentationOutput((dir / "a.labels.raw").string(), other, v, false); }),
      HasSubstr("does not match the volume's"));
}

}  // namespace
}  // namespace voxray
