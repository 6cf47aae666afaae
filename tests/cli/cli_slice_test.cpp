// voxray-cli slice, run as a user runs it, against the workstation's own planes and pixels
// (ui/study): PNG is lossless, so every comparison is exact.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/wait.h>

#include "mpr_planes.h"
#include "slice_image.h"
#include "voxray/engine/input_flags.h"
#include "voxray/io/image.h"
#include "voxray/io/phantom.h"

using namespace voxray;

namespace {

const std::string kCthead = std::string(VOXRAY_DATA_DIR) +
                            "/stanford/CThead --raw-dims 256,256 --raw-type i16 --raw-endian big "
                            "--raw-spacing 1,1,2 --raw-rescale 1,-1024 --raw-axes LPI";

Volume loadCthead() {
  return loadVolume(std::string(VOXRAY_DATA_DIR) + "/stanford/CThead",
                    loadOptionsFromFlags({{"raw-dims", "256,256"},
                                          {"raw-type", "i16"},
                                          {"raw-endian", "big"},
                                          {"raw-spacing", "1,1,2"},
                                          {"raw-rescale", "1,-1024"},
                                          {"raw-axes", "LPI"}}));
}

struct CliRun {
  int exitCode;
  std::string err;
};

// voxray-cli slice ARGS -o NAME.png in the build tree; the image in *IMAGE when it worked.
CliRun slice(const std::string& args, const std::string& name, Image* image = nullptr) {
  const std::filesystem::path dir =
      std::filesystem::path(VOXRAY_CLI).parent_path().parent_path() / "tests/cli/slice";
  std::filesystem::create_directories(dir);
  const std::string png = (dir / (name + ".png")).string(), log = (dir / (name + ".log")).string();
  std::filesystem::remove(png);
  const int status = std::system(
      (std::string(VOXRAY_CLI) + " slice " + args + " -o " + png + " 2> " + log).c_str());
  std::stringstream err;
  err << std::ifstream(log).rdbuf();
  CliRun r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, err.str()};
  if (r.exitCode == 0 && image) *image = readImage(png);
  return r;
}

void expectSameImage(const Image& got, const Image& want) {
  ASSERT_EQ(got.width, want.width);
  ASSERT_EQ(got.height, want.height);
  EXPECT_TRUE(got.rgba == want.rgba);
}

}  // namespace

TEST(CliSlice, AnAxialIndexIsTheViewsSlicePixelForPixel) {
  const Volume v = loadCthead();
  Image png;
  ASSERT_EQ(slice(kCthead + " --plane axial --index 56 --wl 2000,500", "axial56", &png).exitCode,
            0);
  expectSameImage(png, renderSlice(v, sliceAxes(v.direction, Orientation::Axial), 56, {2000, 500},
                                   Interp::Linear));
}

TEST(CliSlice, MillimetresPickTheSliceAtThatPatientPosition) {
  const Volume v = loadCthead();
  // Coronal slice 100 lies at y = voxelToPatientMm(...).y (LPS: posterior positive).
  const double y = voxelToPatientMm(v, {0, 100, 0}).y;
  Image byMm, byIndex;
  ASSERT_EQ(
      slice(kCthead + " --plane coronal --mm " + std::to_string(y), "coronalMm", &byMm).exitCode,
      0);
  ASSERT_EQ(slice(kCthead + " --plane coronal --index 100", "coronal100", &byIndex).exitCode, 0);
  expectSameImage(byMm, byIndex);
  // Axial positions are S (up) even though CThead's slices run head to feet (LPI).
  const double z = voxelToPatientMm(v, {0, 0, 40}).z;
  ASSERT_EQ(slice(kCthead + " --plane axial --mm " + std::to_string(z), "axialMm", &byMm).exitCode,
            0);
  ASSERT_EQ(slice(kCthead + " --plane axial --index 40", "axial40", &byIndex).exitCode, 0);
  expectSameImage(byMm, byIndex);
}

TEST(CliSlice, AnObliqueSlabIsTheModelsPlaneAndSlab) {
  const Volume v = makeHeadPhantom(64);
  const glm::dvec3 point(10.0, -20.0, 15.0), normal(0.0, 1.0, 1.0);
  Image png;
  const CliRun r = slice(
      "--phantom-size 64 --normal 0,1,1 --point 10,-20,15 --slab 12 "
      "--slab-mode mean --wl 400,40",
      "oblique", &png);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const ObliqueView view = viewForNormal(v.direction, normal);
  EXPECT_EQ(view.orientation, Orientation::Axial);  // ties go to the first nearest view
  const PlaneGrid g = viewPlane(v, sliceAxes(v.direction, view.orientation),
                                patientMmToVoxel(v, point), view.rotation);
  expectSameImage(png, renderPlane(v, g, {400, 40}, Interp::Linear, {12.0, SlabMode::Mean}));
  // 4 mm voxels: a sample every 4 mm from face to face.
  EXPECT_NE(r.err.find("slab 12 mm mean (4 samples per pixel)"), std::string::npos) << r.err;
}

TEST(CliSlice, BadPlanesSayWhatIsWrong) {
  CliRun r = slice("--phantom-size 32 --plane axial --index 32", "bad");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--index 32: the axial plane has slices 0 to 31"), std::string::npos)
      << r.err;
  r = slice("--phantom-size 32 --normal 0,0,0", "bad");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--normal must be a non-zero direction"), std::string::npos) << r.err;
  r = slice("--phantom-size 32 --point 0,0,900", "bad");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("the plane misses the volume"), std::string::npos) << r.err;
  r = slice("--phantom-size 32 --wl 0,40", "bad");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("window width must be above 0"), std::string::npos) << r.err;
  EXPECT_EQ(slice("--phantom-size 32 --slab-mode max", "bad").exitCode, 2);  // usage
  EXPECT_EQ(slice("--phantom-size 32 --index 3 --mm 4", "bad").exitCode, 2);
}
