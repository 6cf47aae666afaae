// Mesh files read back by an independent reader (trimesh, in the venv scripts/bootstrap makes).
#include "voxray/io/mesh_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>

#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include "mesh_test_scenes.h"
#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray {
namespace {

class MeshFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("voxray-mesh-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> filesThere() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_))
      names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  // What trimesh reads from each file, as mesh_readback.py prints it.
  static nlohmann::json readBack(const std::vector<std::string>& paths) {
    if (!fs::exists(VOXRAY_PYTHON)) {
      ADD_FAILURE() << "No Python with trimesh at " VOXRAY_PYTHON ": run scripts/bootstrap";
      return nlohmann::json::array();
    }
    std::string command = "'" VOXRAY_PYTHON "' '" VOXRAY_MESH_READBACK "'";
    for (const auto& p : paths) command += " '" + p + "'";
    std::FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    char buffer[4096];
    while (size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
    EXPECT_EQ(pclose(pipe), 0) << command;
    return nlohmann::json::parse(out);
  }

  fs::path dir_;
};

// Two segments: the ball (label 1) and a box of 10x6x4 voxels (label 2, green) beside it.
Segmentation ballAndBox() {
  Segmentation s = sphereSegmentation(10.0, 1.0);
  for (int z = 2; z < 6; ++z)
    for (int y = 2; y < 8; ++y)
      for (int x = 2; x < 12; ++x) s.labels[s.grid.index(x, y, z)] = 2;
  Segment box;
  box.label = 2;
  box.name = "Box / left?";
  box.colour = {0.0f, 0.8f, 0.2f};
  s.segments.push_back(box);
  return s;
}

// The LPS box the voxels of LABEL cover (their centres +- half a voxel).
std::pair<glm::dvec3, glm::dvec3> voxelBounds(const Segmentation& s, uint8_t label) {
  glm::dvec3 lo(1e9), hi(-1e9);
  for (int z = 0; z < s.grid.dims.z; ++z)
    for (int y = 0; y < s.grid.dims.y; ++y)
      for (int x = 0; x < s.grid.dims.x; ++x)
        if (s.labels[s.grid.index(x, y, z)] == label)
          for (int c = 0; c < 8; ++c) {
            const glm::dvec3 corner =
                glm::dvec3(x, y, z) + glm::dvec3(c & 1, (c >> 1) & 1, (c >> 2) & 1) - 0.5;
            lo = glm::min(lo, s.grid.toPatient(corner));
            hi = glm::max(hi, s.grid.toPatient(corner));
          }
  return {lo, hi};
}

TEST_F(MeshFile, StlReadByTrimeshHasTheSegmentsBoundsAndIsWatertight) {
  const Segmentation s = sphereSegmentation(40.0, 0.7);
  writeMeshFile(file("ball.stl"), s, {1});
  const auto r = readBack({file("ball.stl")})[0];
  const auto [lo, hi] = voxelBounds(s, 1);
  // Within one voxel (0.7 mm): the surface runs through the outer voxels' faces, smoothing
  // pulls it in by a fraction of a voxel.
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(r["bounds"][0][a].get<double>(), lo[a], 0.7) << "axis " << a;
    EXPECT_NEAR(r["bounds"][1][a].get<double>(), hi[a], 0.7) << "axis " << a;
  }
  EXPECT_TRUE(r["watertight"].get<bool>());
  const double volume = 4.0 / 3.0 * std::numbers::pi * 40.0 * 40.0 * 40.0;
  EXPECT_NEAR(r["volume"].get<double>(), volume, 0.01 * volume);  // positive: faces point out
  EXPECT_EQ(r["header"].get<std::string>(), "Voxray mesh, LPS mm: Ball");
}

TEST_F(MeshFile, RasNegatesXAndYOfLps) {
  const Segmentation s = ballAndBox();
  writeMeshFile(file("lps.stl"), s, {2});
  MeshFileOptions ras;
  ras.coordinates = MeshCoordinates::Ras;
  writeMeshFile(file("ras.stl"), s, {2}, ras);
  const auto r = readBack({file("lps.stl"), file("ras.stl")});
  const auto& lps = r[0]["bounds"];
  const auto& rasBounds = r[1]["bounds"];
  for (int a = 0; a < 2; ++a) {  // x, y: min and max swap and change sign (1e-3: float text)
    EXPECT_NEAR(rasBounds[0][a].get<double>(), -lps[1][a].get<double>(), 1e-3);
    EXPECT_NEAR(rasBounds[1][a].get<double>(), -lps[0][a].get<double>(), 1e-3);
  }
  EXPECT_NEAR(rasBounds[0][2].get<double>(), lps[0][2].get<double>(), 1e-3);
  EXPECT_NEAR(rasBounds[1][2].get<double>(), lps[1][2].get<double>(), 1e-3);
  EXPECT_GT(r[1]["volume"].get<double>(), 0.0);  // a rotation: still facing outwards
  EXPECT_EQ(r[1]["header"].get<std::string>(), "Voxray mesh, RAS mm: Box / left?");
  // The box lies at LPS x from the origin -30 + 1.5 .. -30 + 11.5 mm: in RAS 18.5 .. 28.5.
  EXPECT_NEAR(rasBounds[0][0].get<double>(), 18.5, 0.5);
  EXPECT_NEAR(rasBounds[1][0].get<double>(), 28.5, 0.5);
}

TEST_F(MeshFile, ObjCarriesEachSegmentsColourInItsMtl) {
  const Segmentation s = ballAndBox();
  MeshFileOptions o;
  o.coordinates = MeshCoordinates::Ras;
  writeMeshFile(file("both.obj"), s, {}, o);
  EXPECT_EQ(filesThere(), (std::vector<std::string>{"both.mtl", "both.obj"}));
  const auto r = readBack({file("both.obj")})[0];
  ASSERT_EQ(r["parts"].get<int>(), 2);
  std::vector<std::vector<double>> colours = r["colours"];
  std::sort(colours.begin(), colours.end());
  // trimesh keeps colours as 8-bit: within 1/255.
  ASSERT_EQ(colours.size(), 2u);
  EXPECT_NEAR(colours[0][0], 0.0, 1 / 255.0);
  EXPECT_NEAR(colours[0][1], 0.8, 1 / 255.0);
  EXPECT_NEAR(colours[0][2], 0.2, 1 / 255.0);
  EXPECT_NEAR(colours[1][0], 1.0, 1 / 255.0);
  EXPECT_NEAR(colours[1][1], 0.5, 1 / 255.0);
  EXPECT_NEAR(colours[1][2], 0.0, 1 / 255.0);
  EXPECT_NE(r["header"].get<std::string>().find("coordinates: RAS millimetres"), std::string::npos);
  EXPECT_TRUE(r["watertight"].get<bool>());
}

TEST_F(MeshFile, PlyHasFaceColoursAndNamesItsFrame) {
  const Segmentation s = ballAndBox();
  writeMeshFile(file("both.ply"), s, {1, 2});
  const auto r = readBack({file("both.ply")})[0];
  std::vector<std::vector<int>> colours = r["colours"];
  std::sort(colours.begin(), colours.end());
  EXPECT_EQ(colours, (std::vector<std::vector<int>>{{0, 204, 51}, {255, 128, 0}}));
  EXPECT_NE(r["header"].get<std::string>().find("coordinates: LPS millimetres"), std::string::npos);
  EXPECT_TRUE(r["watertight"].get<bool>());
}

TEST_F(MeshFile, PerSegmentFilesAreNamedByLabelAndSanitisedName) {
  const Segmentation s = ballAndBox();
  MeshFileOptions o;
  o.perSegment = true;
  writeMeshFile(file("model.stl"), s, {}, o);
  EXPECT_EQ(filesThere(), (std::vector<std::string>{"model_1_Ball.stl", "model_2_Box_left.stl"}));
  const auto r = readBack({file("model_1_Ball.stl"), file("model_2_Box_left.stl")});
  EXPECT_TRUE(r[0]["watertight"].get<bool>());
  // The box's 10x6x4 voxels of 1 mm: 240 mm3 less its bevelled and smoothed edges.
  EXPECT_GT(r[1]["volume"].get<double>(), 180.0);
  EXPECT_LT(r[1]["volume"].get<double>(), 240.0);
}

TEST_F(MeshFile, RefusesToOverwriteUnlessTold) {
  const Segmentation s = ballAndBox();
  { std::ofstream(file("ball.stl")) << "mine"; }
  try {
    writeMeshFile(file("ball.stl"), s, {1});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("exists already"), std::string::npos) << e.what();
  }
  std::ifstream in(file("ball.stl"));
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "mine");
  MeshFileOptions o;
  o.overwrite = true;
  writeMeshFile(file("ball.stl"), s, {1}, o);
  EXPECT_GT(fs::file_size(file("ball.stl")),
            84u + 50u * 1000u);  // header + count + >1000 triangles
  EXPECT_EQ(filesThere(), (std::vector<std::string>{"ball.stl"}));  // no temporary left
}

TEST_F(MeshFile, ZeroVoxelSegmentIsRefusedAndNothingIsWritten) {
  Segmentation s = ballAndBox();
  Segment empty;
  empty.label = 5;
  empty.name = "Tumour";
  s.segments.push_back(empty);
  for (const bool perSegment : {false, true}) {
    MeshFileOptions o;
    o.perSegment = perSegment;
    try {
      writeMeshFile(file("out.obj"), s, {1, 5}, o);
      FAIL() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::Input);
      EXPECT_EQ(std::string(e.what()),
                "Segment \"Tumour\" (label 5) has no voxels, so it has no surface: paint or "
                "threshold it first, "
                "or leave it out.");
    }
    EXPECT_TRUE(filesThere().empty());
  }
}

TEST_F(MeshFile, UnknownExtensionAndLabelAreRefused) {
  const Segmentation s = ballAndBox();
  EXPECT_THROW(writeMeshFile(file("ball.vtk"), s, {1}), Error);
  EXPECT_THROW(writeMeshFile(file("ball.stl"), s, {9}), Error);
  EXPECT_THROW(writeMeshFile(file("no/such/folder/ball.stl"), s, {1}), Error);
  EXPECT_TRUE(filesThere().empty());
  EXPECT_EQ(meshFormatFor("A.STL"), MeshFormat::Stl);
  EXPECT_EQ(meshFormatFor("a.Obj"), MeshFormat::Obj);
}

}  // namespace
}  // namespace voxray
