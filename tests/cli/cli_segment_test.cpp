// voxray-cli segment against the recipe run in this process: the same label map voxel for
// voxel and the same statistics, on the embedded head phantom (no data files needed).
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "command_run.h"
#include "voxray/io/phantom.h"
#include "voxray/io/segment_files.h"
#include "voxray/io/segment_mesh.h"
#include "voxray/io/segment_recipe.h"
#include "voxray/io/segment_stats.h"

namespace voxray {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using test::CommandResult;

CommandResult cli(const std::string& args) {
  return test::runCommand("timeout 120 " + std::string(VOXRAY_CLI) + " segment --phantom-size 96 " +
                          args + " 2>&1");
}

class CliSegment : public test::ScratchFolderTest {
 protected:
  CliSegment() : ScratchFolderTest("voxray-cli-segment-") {}
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
  const CommandResult run =
      cli("--threshold 300,3000 --seed " + seed +
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
  // The area of the smoothed, unsimplified surface, as makeSurface gives it in process (the
  // sum runs over the same triangles; 1e-9 leaves room for the order threads add them in).
  SurfaceOptions unsimplified;
  unsimplified.targetTriangles = 0;
  const double area = makeSurface(expected, 1, unsimplified).areaMm2;
  EXPECT_NEAR(stats["surface_mm2"].get<double>(), area, area * 1e-9);

  // Again onto the same file: refused without --force.
  const CommandResult again = cli("--threshold 300,3000 -o " + path("skull.labels.raw"));
  EXPECT_EQ(again.exitCode, 1);
  EXPECT_THAT(again.output, HasSubstr("exists: give --force to replace it, or another name."));
  // An existing statistics file is refused before the work too: no label map is written.
  const CommandResult statsKept = cli("--threshold 300,3000 -o " + path("other.labels.raw") +
                                      " --stats-json " + path("stats.json"));
  EXPECT_EQ(statsKept.exitCode, 1);
  EXPECT_THAT(statsKept.output, HasSubstr("stats.json exists: give --force to replace it"));
  EXPECT_FALSE(fs::exists(path("other.labels.raw")));
}

TEST_F(CliSegment, StatsToStdoutAndASeedInMmGiveTheSameAsTheVoxelSeed) {
  const Volume v = makeHeadPhantom(96);
  SegmentRecipe r;
  r.threshold = {300.0, 3000.0};
  r.seed = firstInRange(v, r.threshold);
  const auto expected = segmentStats(segmentationFromRecipe(v, r), v, 1);
  const glm::dvec3 mm = gridOf(v).toPatient(glm::dvec3(*r.seed));
  const CommandResult run =
      cli("--threshold 300,3000 --seed-mm " + std::to_string(mm.x) + "," + std::to_string(mm.y) +
          "," + std::to_string(mm.z) + " --stats-json -");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto stats = nlohmann::json::parse(run.output)["segments"][0];
  EXPECT_EQ(stats["voxels"].get<size_t>(), expected.voxels);
  EXPECT_DOUBLE_EQ(stats["mean"].get<double>(), *expected.mean);
}

// Binary STL: 80-byte header, a triangle count, 50 bytes per triangle (normal, 3 vertices, 2).
struct Stl {
  std::string header;
  glm::dvec3 lo{1e30}, hi{-1e30};
  size_t triangles = 0;
};
Stl readStl(const std::string& path) {
  const auto bytes = readBytes(path);
  Stl stl;
  if (bytes.size() < 84) return stl;
  stl.header.assign(bytes.begin(), bytes.begin() + 80);
  uint32_t n = 0;
  std::memcpy(&n, bytes.data() + 80, 4);
  if (bytes.size() != 84 + size_t(n) * 50) return stl;
  stl.triangles = n;
  for (size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      float p[3];
      std::memcpy(p, bytes.data() + 84 + t * 50 + 12 + size_t(k) * 12, 12);
      for (int a = 0; a < 3; ++a) {
        stl.lo[a] = std::min(stl.lo[a], double(p[a]));
        stl.hi[a] = std::max(stl.hi[a], double(p[a]));
      }
    }
  return stl;
}

// Every format -o names goes through the writers the workstation uses: the label maps come
// back voxel for voxel, the STL spans the segment's voxels (LPS, or RAS with x and y negated),
// and a dvr with --labels FILE is the one --labels-raw gives for the same map.
TEST_F(CliSegment, EveryOutputFormatHoldsTheSameSegment) {
  const Volume v = makeHeadPhantom(96);
  SegmentRecipe r;
  r.threshold = {300.0, 3000.0};
  r.seed = firstInRange(v, r.threshold);
  r.name = "Skull";
  const Segmentation expected = segmentationFromRecipe(v, r);
  const std::string seed =
      std::to_string(r.seed->x) + ":" + std::to_string(r.seed->y) + ":" + std::to_string(r.seed->z);
  const std::string args = "--threshold 300,3000 --seed " + seed + " --name Skull -o ";
  for (const char* name : {"skull.labels.raw", "skull.nii.gz", "skull.seg.nrrd", "skull.stl"}) {
    const CommandResult run = cli(args + path(name));
    ASSERT_EQ(run.exitCode, 0) << name << "\n" << run.output;
  }
  ASSERT_EQ(cli(args + path("skull-ras.stl") + " --ras").exitCode, 0);
  for (const char* name : {"skull.nii.gz", "skull.seg.nrrd"}) {
    const Segmentation back = readSegmentationFile(path(name), v);
    EXPECT_EQ(back.labels, expected.labels) << name;
  }
  EXPECT_EQ(readSegmentationFile(path("skull.seg.nrrd"), v).segments.at(0).name, "Skull");

  // The voxels' extent in LPS mm; the smoothed surface lies within a voxel of it.
  const VoxelGrid& g = expected.grid;
  glm::dvec3 lo(1e30), hi(-1e30);
  for (int z = 0; z < g.dims.z; ++z)
    for (int y = 0; y < g.dims.y; ++y)
      for (int x = 0; x < g.dims.x; ++x)
        if (expected.labels[g.index(x, y, z)] == 1) {
          const glm::dvec3 p = g.toPatient(glm::dvec3(x, y, z));
          lo = glm::min(lo, p);
          hi = glm::max(hi, p);
        }
  const Stl lps = readStl(path("skull.stl"));
  const Stl ras = readStl(path("skull-ras.stl"));
  ASSERT_GT(lps.triangles, 1000u);
  EXPECT_THAT(lps.header, HasSubstr("LPS mm"));
  EXPECT_THAT(ras.header, HasSubstr("RAS mm"));
  const double voxel = std::max({g.spacingMm.x, g.spacingMm.y, g.spacingMm.z});
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(lps.lo[a], lo[a], voxel) << "axis " << a;
    EXPECT_NEAR(lps.hi[a], hi[a], voxel) << "axis " << a;
    const double sign = a < 2 ? -1.0 : 1.0;
    EXPECT_NEAR(ras.lo[a], a < 2 ? sign * lps.hi[a] : lps.lo[a], 1e-3) << "axis " << a;
    EXPECT_NEAR(ras.hi[a], a < 2 ? sign * lps.lo[a] : lps.hi[a], 1e-3) << "axis " << a;
  }

  // Shown alone with the TF's colours (blend 0), the segment renders the same from either file.
  const std::string render = "timeout 120 " + std::string(VOXRAY_CLI) +
                             " render --phantom-size 96 --mode dvr --size 96x96"
                             " --segment-mask show:1 --segment-blend 0 ";
  ASSERT_EQ(std::system((render + "--labels " + path("skull.seg.nrrd") + " -o " +
                         path("from-nrrd.png") + " > /dev/null 2>&1")
                            .c_str()),
            0);
  ASSERT_EQ(std::system((render + "--labels-raw " + path("skull.labels.raw") + " -o " +
                         path("from-raw.png") + " > /dev/null 2>&1")
                            .c_str()),
            0);
  EXPECT_EQ(readBytes(path("from-nrrd.png")), readBytes(path("from-raw.png")));
  EXPECT_GT(readBytes(path("from-nrrd.png")).size(), 100u);
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
           {"--threshold 5000,6000 -o " + path("x.stl"),
            "No visible segment has voxels, so there is no surface to write"},
           {"--threshold 300,3000 -o " + path("x.dcm"),
            "A DICOM SEG needs the source series' Study Instance UID"},
           {"--threshold 300,3000 -o " + path("x.png"), "give an output ending in .stl"},
           {"--threshold 300,3000", "give -o OUT (a label map or mesh) and/or --stats-json"}}) {
    const CommandResult r = cli(c.args);
    EXPECT_EQ(r.exitCode, 1) << c.args << "\n" << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.message)) << c.args;
  }
}

}  // namespace
}  // namespace voxray
