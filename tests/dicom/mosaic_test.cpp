// Siemens mosaics (issue 36): the project's mosaic phantom (a known oblique volume per time
// point, tiled as Siemens tiles it) demosaiced into its volumes; the same files and a real
// Siemens mosaic (transfer-syntaxes/1.dcm) converted by dcm2niix and read by nibabel agree
// with Voxray's geometry and voxels; bad NumberOfImagesInMosaic refused naming the attribute.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>

#include "../io/test_support.h"
#include "test_data.h"
#include "voxray/io/load.h"
#include "voxray/io/phantom_series.h"

namespace voxray {
namespace {

namespace fs = std::filesystem;

// Positions are written as DS of 10 significant digits (about 1e-7 mm here) and dcm2niix
// stores its affine as float32 (about 1e-5 mm at 100 mm): 1e-3 mm is far above both and far
// below a voxel (2.5 mm), so it catches any misplaced tile or slice.
constexpr double kPositionTolerance = 1e-3;

double valueAt(const Volume& v, glm::ivec3 ijk) {
  return v.toPhysical(
      v.voxels[size_t(ijk.x) +
               size_t(v.dims.x) * (size_t(ijk.y) + size_t(v.dims.y) * size_t(ijk.z))]);
}

glm::dvec3 centre(const Volume& v, glm::dvec3 ijk) {
  return v.originMm + v.direction * (ijk * v.spacingMm);
}

// The voxel of V whose centre is at LPS point P (rounded), and how far that centre is from P.
glm::ivec3 voxelAt(const Volume& v, const glm::dvec3& p, double& off) {
  const glm::dvec3 f = glm::inverse(v.direction) * (p - v.originMm) / v.spacingMm;
  const glm::ivec3 i(glm::round(f));
  off = glm::length(centre(v, glm::dvec3(i)) - p);
  return i;
}

// Every voxel of every time point of VOLUMES equals the phantom's value at its LPS centre.
void expectPhantomVolumes(const MosaicPhantom& p, const std::vector<Volume>& volumes) {
  ASSERT_EQ(volumes.size(), size_t(p.timePoints));
  for (int t = 0; t < p.timePoints; ++t) {
    const Volume& v = volumes[size_t(t)];
    SCOPED_TRACE("time point " + std::to_string(t));
    EXPECT_EQ(v.timePoint, t);
    EXPECT_EQ(v.timePoints, p.timePoints);
    ASSERT_EQ(v.dims, p.dims);
    EXPECT_NEAR(v.spacingMm.x, p.spacingMm.x, 1e-9);
    EXPECT_NEAR(v.spacingMm.y, p.spacingMm.y, 1e-9);
    EXPECT_NEAR(v.spacingMm.z, p.spacingMm.z, 1e-6);
    size_t wrong = 0, misplaced = 0;
    for (int k = 0; k < p.dims.z; ++k)
      for (int j = 0; j < p.dims.y; ++j)
        for (int i = 0; i < p.dims.x; ++i) {
          const glm::ivec3 known(i, j, k);
          double off = 0;
          const glm::ivec3 got = voxelAt(v, p.position(known), off);
          if (off > kPositionTolerance || glm::any(glm::lessThan(got, glm::ivec3(0))) ||
              glm::any(glm::greaterThanEqual(got, v.dims))) {
            ++misplaced;
            continue;
          }
          wrong += valueAt(v, got) != p.value(known, t);
        }
    EXPECT_EQ(misplaced, 0u);
    EXPECT_EQ(wrong, 0u);
  }
}

TEST(Mosaic, DemosaicedVolumesEqualTheKnownVolumes) {
  test::TempDir dir;
  MosaicPhantom p;  // 14 slices of 40 x 32 in a 4 x 4 tiling: two tiles empty
  writeMosaicPhantom(dir.file("mr"), p);
  const std::vector<Volume> all = loadVolumeSeries(dir.file("mr"));
  expectPhantomVolumes(p, all);
  // Chosen voxels at their analytic LPS centres: the corners and the sphere's middle.
  const Volume& v = all.front();
  for (glm::ivec3 ijk : {glm::ivec3(0, 0, 0), glm::ivec3(39, 0, 0), glm::ivec3(0, 31, 0),
                         glm::ivec3(0, 0, 13), glm::ivec3(39, 31, 13), glm::ivec3(17, 9, 6)}) {
    const glm::dvec3 d = centre(v, glm::dvec3(ijk)) - p.position(ijk);
    EXPECT_LT(glm::length(d), kPositionTolerance) << ijk.x << "," << ijk.y << "," << ijk.z;
  }
  EXPECT_EQ(v.modality, "MR");
  EXPECT_TRUE(test::anyContains(v.warnings, "this is time point 0 of 0-2"));
  // The sphere's signal follows the time points: 1000, 1150, 1300.
  EXPECT_EQ(test::physicalMax(all[2]), 1300.0);
}

TEST(Mosaic, TheCsaHeaderAloneGivesTheSliceCount) {
  test::TempDir dir;
  MosaicPhantom p;
  p.writeMrHeaderImages = false;
  p.timePoints = 2;
  writeMosaicPhantom(dir.file("mr"), p);
  expectPhantomVolumes(p, loadVolumeSeries(dir.file("mr")));
}

// What a wrong NumberOfImagesInMosaic says: the file is skipped, naming the attribute.
std::string badMosaic(std::optional<int> mrHeader, std::optional<int> csa, bool writeMr = true) {
  test::TempDir dir;
  MosaicPhantom p;
  p.timePoints = 1;
  p.mrHeaderImages = mrHeader;
  p.csaImages = csa;
  p.writeMrHeaderImages = writeMr;
  writeMosaicPhantom(dir.file("mr"), p);
  return test::importError(dir.file("mr"));
}

TEST(Mosaic, AWrongNumberOfImagesInMosaicIsRefusedNamingIt) {
  EXPECT_THAT(badMosaic(0, std::nullopt),
              testing::HasSubstr("1 file(s) skipped: a Siemens mosaic whose (0019,100A) "
                                 "NumberOfImagesInMosaic is 0; a mosaic holds 1 slice or more"));
  // 4 x 4 tiles of 40 x 32: 17 images would need 5 x 5 tiles, which 160 x 128 does not hold.
  EXPECT_THAT(badMosaic(17, std::nullopt),
              testing::HasSubstr("(0019,100A) NumberOfImagesInMosaic is 17, which Siemens tiles "
                                 "5 x 5, but the 160x128 image does not divide into that square "
                                 "tiling"));
  EXPECT_THAT(badMosaic(65535, std::nullopt),
              testing::HasSubstr("(0019,100A) NumberOfImagesInMosaic is 65535: more tiles (256 x "
                                 "256) than the 160x128 image has pixels"));
  EXPECT_THAT(badMosaic(std::nullopt, 200000, false),
              testing::HasSubstr("NumberOfImagesInMosaic of the CSA image header (0029,1010) is "
                                 "200000: more slices than any real series"));
  EXPECT_THAT(badMosaic(40000, std::nullopt),
              testing::HasSubstr("NumberOfImagesInMosaic is 40000: more tiles (200 x 200) than "
                                 "the 160x128 image has pixels"));
  EXPECT_THAT(
      badMosaic(std::nullopt, 0, false),
      testing::HasSubstr("NumberOfImagesInMosaic of the CSA image header (0029,1010) is 0"));
  EXPECT_THAT(badMosaic(std::nullopt, 1 << 30, false),
              testing::HasSubstr("without NumberOfImagesInMosaic ((0019,100A) or the CSA image "
                                 "header (0029,1010))"));
}

// Runs dcm2niix on DICOM_DIR and nibabel (tests/dicom/nifti_lps_voxels.py) on what it wrote:
// one line a voxel, "x y z v0 v1 ..." in LPS.
std::vector<std::string> dcm2niixVoxels(const std::string& dicomDir, const fs::path& out) {
  fs::create_directories(out);
  const std::string convert = "dcm2niix -b n -z n -f out -o '" + out.string() + "' '" + dicomDir +
                              "' > '" + (out / "dcm2niix.log").string() + "' 2>&1";
  EXPECT_EQ(std::system(convert.c_str()), 0) << convert;
  std::string nii;
  for (const auto& e : fs::directory_iterator(out))
    if (e.path().extension() == ".nii") nii = e.path().string();
  if (nii.empty()) {
    ADD_FAILURE() << "dcm2niix wrote no NIfTI for " << dicomDir;
    return {};
  }
  const std::string python = VOXRAY_PYTHON;
  if (!fs::exists(python)) {
    ADD_FAILURE() << python << " is missing: run scripts/bootstrap (it makes the .venv of the "
                  << "independent readers)";
    return {};
  }
  const std::string read = python + " " + VOXRAY_TEST_SOURCE_DIR + "/nifti_lps_voxels.py '" + nii +
                           "' > '" + (out / "voxels.txt").string() + "'";
  EXPECT_EQ(std::system(read.c_str()), 0) << read;
  std::ifstream in(out / "voxels.txt");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Every NIfTI voxel's LPS centre is a voxel centre of VOLUMES within 1e-3 mm and holds the
// same value at every time point; every voxel of VOLUMES is met once.
void expectSameAsNifti(const std::vector<Volume>& volumes, const std::vector<std::string>& lines) {
  ASSERT_FALSE(lines.empty());
  const Volume& v = volumes.front();
  std::istringstream shape(lines[0]);
  std::string word;
  int a = 0, b = 0, c = 0, t = 1;
  shape >> word >> a >> b >> c >> t;
  EXPECT_EQ(size_t(a) * size_t(b) * size_t(c), v.voxels.size()) << lines[0];
  EXPECT_EQ(size_t(t), volumes.size()) << lines[0];
  size_t misplaced = 0, wrong = 0;
  double worst = 0;
  std::vector<bool> met(v.voxels.size(), false);
  for (size_t n = 1; n < lines.size(); ++n) {
    std::istringstream line(lines[n]);
    glm::dvec3 p;
    line >> p.x >> p.y >> p.z;
    double off = 0;
    const glm::ivec3 i = voxelAt(v, p, off);
    worst = std::max(worst, off);
    if (off > kPositionTolerance || glm::any(glm::lessThan(i, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(i, v.dims))) {
      ++misplaced;
      continue;
    }
    met[size_t(i.x) + size_t(v.dims.x) * (size_t(i.y) + size_t(v.dims.y) * size_t(i.z))] = true;
    for (const Volume& volume : volumes) {
      double value = 0;
      line >> value;
      wrong += valueAt(volume, i) != value;
    }
  }
  EXPECT_EQ(misplaced, 0u) << "farthest " << worst << " mm";
  EXPECT_LT(worst, kPositionTolerance);
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(std::count(met.begin(), met.end(), false), 0);
}

TEST(Mosaic, Dcm2niixAndNibabelAgreeOnThePhantom) {
  test::TempDir dir;
  MosaicPhantom p;
  writeMosaicPhantom(dir.file("mr"), p);
  expectSameAsNifti(loadVolumeSeries(dir.file("mr")),
                    dcm2niixVoxels(dir.file("mr"), dir.path() / "nii"));
}

// A real Siemens mosaic: 35 slices of 64 x 64 in a 384 x 384 image (6 x 6 tiles), oblique.
TEST(Mosaic, Dcm2niixAndNibabelAgreeOnARealSiemensMosaic) {
  test::TempDir dir;
  fs::create_directories(dir.file("one"));
  fs::copy_file(test::dicomPath("transfer-syntaxes/1.dcm"), dir.file("one/1.dcm"));
  const std::vector<Volume> volumes = loadVolumeSeries(dir.file("one"));
  ASSERT_EQ(volumes.size(), 1u);
  EXPECT_EQ(volumes[0].dims, glm::ivec3(64, 64, 35));
  expectSameAsNifti(volumes, dcm2niixVoxels(dir.file("one"), dir.path() / "nii"));
}

TEST(Mosaic, SlicesStoredDownwardsFollowTheSliceNormalVector) {
  test::TempDir dir;
  MosaicPhantom p;
  p.reverseSlices = true;  // tile k at -(row x column) k spacing, as SliceNormalVector says
  p.timePoints = 1;
  writeMosaicPhantom(dir.file("mr"), p);
  const std::vector<Volume> volumes = loadVolumeSeries(dir.file("mr"));
  expectPhantomVolumes(p, volumes);
  // dcm2niix reads the slice order from SliceNormalVector as well.
  expectSameAsNifti(volumes, dcm2niixVoxels(dir.file("mr"), dir.path() / "nii"));
}

}  // namespace
}  // namespace voxray
