// voxray-cli segment against the recipe run in this process: the same label map voxel for
// voxel and the same statistics, on the embedded head phantom (no data files needed).
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "voxray/io/phantom.h"
#include "voxray/io/segment_recipe.h"
#include "voxray/io/segment_stats.h"

namespace voxray {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

struct Result {
  int exitCode = -1;
  std::string output;
};

Result cli(const std::string& args) {
  const std::string command =
      "timeout 120 " + std::string(VOXRAY_CLI) + " segment --phantom-size 96 " + args + " 2>&1";
  Result r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) r.output.append(buffer, n);
  const int status = pclose(pipe);
  if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
  return r;
}

class CliSegment : public ::testing::Test {
 protected:
  CliSegment() {
    std::random_device seed;
    dir_ = fs::temp_directory_path() / ("voxray-cli-segment-" + std::to_string(seed()));
    fs::create_directories(dir_);
  }
  ~CliSegment() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

std::vector<uint8_t> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The first voxel of the centre row (y, z at the middle) whose value lies in the range.
glm::ivec3 firstInRange(const Volume& v, HuRange r) {
  const int y = v.dims.y / 2, z = v.dims.z / 2;
  for (int x = 0; x < v.dims.x; ++x) {
    const double hu = v.toPhysical(v.at(x, y, z));
    if (hu >= r.lo && hu <= r.hi) return {x, y, z};
  }
  return {-1, -1, -1};
}

TEST_F(CliSegment, TheLabelMapAndStatisticsAreTheRecipesInProcessVoxelForVoxel) {
  const Volume v = makeHeadPhantom(96);
  SegmentRecipe r;
  r.threshold = {300.0, 3000.0};
  r.seed = firstInRange(v, r.threshold);
  ASSERT_GE(r.seed->x, 0) << "the phantom has no bone on its centre row";
  r.connectivity = Connectivity::Full26;
  r.keepLargest = true;
  r.fillHoles = true;
  r.marginMm = 1.5;
  r.smoothMm = 3.0;
  r.name = "Skull";
  const Segmentation expected = segmentationFromRecipe(v, r);
  const auto expectedStats = segmentStats(expected, v, 1);
  ASSERT_GT(expectedStats.voxels, 1000u);

  const std::string seed =
      std::to_string(r.seed->x) + ":" + std::to_string(r.seed->y) + ":" + std::to_string(r.seed->z);
  const Result run = cli("--threshold 300,3000 --seed " + seed +
                         " --connectivity 26 --keep-largest --fill-holes --margin 1.5 --smooth 3 "
                         "--name Skull --colour 255,128,0 -o " +
                         path("skull.labels.raw") + " --stats-json " + path("stats.json"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(readBytes(path("skull.labels.raw")), expected.labels);

  std::ifstream side(path("skull.labels.json"));
  const auto sidecar = nlohmann::json::parse(side);
  EXPECT_EQ(sidecar["dims"], nlohmann::json({96, 96, 96}));
  EXPECT_EQ(sidecar["segments"][0]["name"], "Skull");
  EXPECT_NEAR(sidecar["segments"][0]["colour"][1].get<double>(), 128.0 / 255.0, 1e-6);

  std::ifstream statsFile(path("stats.json"));
  const auto stats = nlohmann::json::parse(statsFile)["segments"][0];
  EXPECT_EQ(stats["voxels"].get<size_t>(), expectedStats.voxels);
  EXPECT_DOUBLE_EQ(stats["volume_ml"].get<double>(), expectedStats.volumeMl);
  EXPECT_DOUBLE_EQ(stats["mean"].get<double>(), *expectedStats.mean);
  EXPECT_DOUBLE_EQ(stats["sd"].get<double>(), *expectedStats.sd);
  EXPECT_DOUBLE_EQ(stats["median"].get<double>(), *expectedStats.median);
  EXPECT_DOUBLE_EQ(stats["min"].get<double>(), *expectedStats.min);
  EXPECT_DOUBLE_EQ(stats["max"].get<double>(), *expectedStats.max);
  EXPECT_EQ(stats["unit"], "HU");

  // Again onto the same file: refused without --force.
  const Result again = cli("--threshold 300,3000 -o " + path("skull.labels.raw"));
  EXPECT_EQ(again.exitCode, 1);
  EXPECT_THAT(again.output, HasSubstr("exists: give --force to replace it, or another name."));
}

TEST_F(CliSegment, StatsToStdoutAndASeedInMmGiveTheSameAsTheVoxelSeed) {
  const Volume v = makeHeadPhantom(96);
  SegmentRecipe r;
  r.threshold = {300.0, 3000.0};
  r.seed = firstInRange(v, r.threshold);
  const auto expected = segmentStats(segmentationFromRecipe(v, r), v, 1);
  const glm::dvec3 mm = gridOf(v).toPatient(glm::dvec3(*r.seed));
  const Result run = cli("--threshold 300,3000 --seed-mm " + std::to_string(mm.x) + "," +
                         std::to_string(mm.y) + "," + std::to_string(mm.z) + " --stats-json -");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto stats = nlohmann::json::parse(run.output)["segments"][0];
  EXPECT_EQ(stats["voxels"].get<size_t>(), expected.voxels);
  EXPECT_DOUBLE_EQ(stats["mean"].get<double>(), *expected.mean);
}

TEST_F(CliSegment, BadInputsEndWithAMessageAndExitCode1) {
  const std::string out = " -o " + path("x.labels.raw");
  struct Case {
    std::string args, message;
  };
  for (const Case& c : std::vector<Case>{
           {"--threshold 400,300" + out, "is empty: give the lower value first (LO,HI)"},
           {"--threshold 300" + out, "--threshold '300': give LO,HI (physical values, HU)"},
           {"--threshold 300,3000 --seed 200:1:1" + out,
            "The seed 200:1:1 is outside the volume (0:0:0 to 95:95:95)"},
           {"--threshold 300,3000 --seed 1:1" + out, "--seed '1:1': give I:J:K"},
           {"--threshold 300,3000 --seed-mm 9999,0,0" + out, "is outside the volume"},
           {"--threshold 300,3000 --connectivity 8" + out, "--connectivity 8: give 6 or 26"},
           {"--threshold 300,3000 --colour 300,0,0" + out, "give R,G,B (0 to 255 each)"},
           {"--threshold 300,3000 -o " + path("x.stl"),
            ".stl files is not available in this build yet"},
           {"--threshold 300,3000 -o " + path("x.png"), "give an output ending in .stl"},
           {"--threshold 300,3000", "give -o OUT (a label map or mesh) and/or --stats-json"}}) {
    const Result r = cli(c.args);
    EXPECT_EQ(r.exitCode, 1) << c.args << "\n" << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.message)) << c.args;
  }
}

}  // namespace
}  // namespace voxray
