#pragma once
// Helpers for the NIfTI/NRRD/MetaImage tests: dcm2niix conversions into scratch folders and
// a comparison of two volumes in physical space (the value at each LPS voxel centre), which
// holds whatever axis order or flips a converter chose.
#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <glm/glm.hpp>

#include "../test_support.h"
#include "voxray/io/load.h"
#include "voxray/io/volume.h"

namespace voxray::test {

// The message loadVolume(PATH) fails with, which must name the file.
inline std::string loadError(const std::string& path) {
  const std::string m = errorMessage([&] { loadVolume(path); });
  EXPECT_THAT(m, ::testing::HasSubstr(path));
  return m;
}

inline std::string dicomData(const std::string& rel) { return dataPath("dicom/" + rel); }

// Runs dcm2niix on DICOM_DIR into OUT_DIR and returns the one file it wrote (.nii or .nii.gz).
// "-p n": Philips display values (RescaleSlope/Intercept, as Voxray's DICOM import gives), not
// dcm2niix's default "precise" floating-point values from Philips' private scale slope.
inline std::string dcm2niix(const std::string& dicomDir, const std::filesystem::path& outDir,
                            bool gz) {
  const std::string cmd = std::string("dcm2niix -b n -p n -z ") + (gz ? "y" : "n") +
                          " -f out -o '" + outDir.string() + "' '" + dicomDir + "' > '" +
                          (outDir / "dcm2niix.log").string() + "' 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  for (const auto& e : std::filesystem::directory_iterator(outDir)) {
    const std::string name = e.path().filename().string();
    if (name.find(".nii") != std::string::npos) return e.path().string();
  }
  ADD_FAILURE() << "dcm2niix wrote no NIfTI file for " << dicomDir;
  return {};
}

// A text header followed by DATA (a hand-made NRRD or MetaImage file).
inline void writeHeaderFile(const std::string& path, const std::string& header,
                            const std::vector<uint8_t>& data = {}) {
  std::vector<uint8_t> bytes(header.begin(), header.end());
  bytes.insert(bytes.end(), data.begin(), data.end());
  writeBytes(path, bytes);
}

inline double physicalMax(const Volume& v) {
  return v.toPhysical(*std::max_element(v.voxels.begin(), v.voxels.end()));
}

// LPS position of the centre of voxel I.
inline glm::dvec3 voxelCentre(const Volume& v, const glm::dvec3& i) {
  return v.originMm + v.direction * (i * v.spacingMm);
}

struct SpaceComparison {
  size_t voxels = 0;         // voxels of GOT compared
  size_t offGrid = 0;        // centres of GOT that are not centres of TRUTH (> 1e-3 voxel)
  size_t valueMismatch = 0;  // physical values that differ by more than TOLERANCE
  double checksumTruth = 0, checksumGot = 0;  // sums of physical value * (1 + truth index % 7)
};

// Maps every voxel centre of GOT into TRUTH's index space and compares physical values.
inline SpaceComparison compareInSpace(const Volume& truth, const Volume& got, double tolerance) {
  SpaceComparison c;
  const glm::dmat3 toIndex =
      glm::inverse(truth.direction * glm::dmat3(glm::dvec3(truth.spacingMm.x, 0, 0),
                                                glm::dvec3(0, truth.spacingMm.y, 0),
                                                glm::dvec3(0, 0, truth.spacingMm.z)));
  for (int z = 0; z < got.dims.z; ++z)
    for (int y = 0; y < got.dims.y; ++y)
      for (int x = 0; x < got.dims.x; ++x) {
        ++c.voxels;
        const glm::dvec3 t = toIndex * (voxelCentre(got, glm::dvec3(x, y, z)) - truth.originMm);
        const glm::dvec3 r = glm::round(t);
        if (glm::any(glm::greaterThan(glm::abs(t - r), glm::dvec3(1e-3))) ||
            glm::any(glm::lessThan(r, glm::dvec3(0))) ||
            glm::any(glm::greaterThanEqual(r, glm::dvec3(truth.dims)))) {
          ++c.offGrid;
          continue;
        }
        const size_t ti = truth.index(int(r.x), int(r.y), int(r.z));
        const double a = truth.toPhysical(truth.voxels[ti]);
        const double b = got.toPhysical(got.at(x, y, z));
        if (std::abs(a - b) > tolerance) ++c.valueMismatch;
        c.checksumTruth += a * double(1 + ti % 7);
        c.checksumGot += b * double(1 + ti % 7);
      }
  return c;
}

// Same grid in space and same values: dims and spacing agree up to axis order, every voxel
// centre of GOT is one of TRUTH and holds the same physical value (within TOLERANCE).
inline void expectSameInSpace(const Volume& truth, const Volume& got, double tolerance = 0.0) {
  ASSERT_EQ(truth.voxelCount(), got.voxelCount());
  // Dims and spacing up to axis order; then each corner centre of GOT is a corner of TRUTH
  // (origin and directions agree up to the converter's flips and axis order).
  auto sortedDims = [](glm::ivec3 d) {
    std::array<int, 3> a{d.x, d.y, d.z};
    std::sort(a.begin(), a.end());
    return a;
  };
  EXPECT_EQ(sortedDims(truth.dims), sortedDims(got.dims));
  std::array<double, 3> st{truth.spacingMm.x, truth.spacingMm.y, truth.spacingMm.z};
  std::array<double, 3> sg{got.spacingMm.x, got.spacingMm.y, got.spacingMm.z};
  std::sort(st.begin(), st.end());
  std::sort(sg.begin(), sg.end());
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(sg[a], st[a], 1e-4) << "spacing " << a;
  std::vector<glm::dvec3> corners;
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 far = glm::dvec3(truth.dims - 1);
    corners.push_back(
        voxelCentre(truth, glm::dvec3(c & 1 ? far.x : 0, c & 2 ? far.y : 0, c & 4 ? far.z : 0)));
  }
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 far = glm::dvec3(got.dims - 1);
    const glm::dvec3 p =
        voxelCentre(got, glm::dvec3(c & 1 ? far.x : 0, c & 2 ? far.y : 0, c & 4 ? far.z : 0));
    double nearest = 1e300;
    for (const auto& q : corners) nearest = std::min(nearest, glm::length(p - q));
    EXPECT_LT(nearest, 1e-3) << "corner " << c << " of the file's grid is no corner of the DICOM's";
  }
  const SpaceComparison c = compareInSpace(truth, got, tolerance);
  EXPECT_EQ(c.voxels, truth.voxelCount());
  EXPECT_EQ(c.offGrid, 0u);
  EXPECT_EQ(c.valueMismatch, 0u);
  EXPECT_NEAR(c.checksumGot, c.checksumTruth, tolerance * double(c.voxels) * 7 + 1e-6);
}

}  // namespace voxray::test
