// A tilted stack straightened onto an orthogonal grid keeps every acquired pixel: each
// pixel of each stored slice lies inside the volume, and the volume's value there is the
// pixel's within interpolation error. A synthetic series with known geometry and values
// linear in position (which trilinear interpolation reproduces exactly), and the shared
// tilted CTs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../io/test_support.h"
#include "dicom_writer.h"
#include "test_data.h"
#include "voxray/io/statistics.h"

namespace voxray {
namespace {

// Continuous voxel index of the LPS point P in V (V's axes are orthonormal).
glm::dvec3 indexOf(const Volume& v, const glm::dvec3& p) {
  return (glm::transpose(v.direction) * (p - v.originMm)) / v.spacingMm;
}

bool inside(const Volume& v, const glm::dvec3& c) {
  const double eps = 1e-6;
  return glm::all(glm::greaterThanEqual(c, glm::dvec3(-eps))) &&
         glm::all(glm::lessThanEqual(c, glm::dvec3(v.dims - 1) + eps));
}

// Trilinear sample of V at the continuous index C (inside V), in physical units.
double sampleAt(const Volume& v, glm::dvec3 c) {
  c = glm::clamp(c, glm::dvec3(0.0), glm::dvec3(v.dims - 1));
  const glm::ivec3 a = glm::min(glm::ivec3(glm::floor(c)), glm::max(v.dims - 2, 0));
  const glm::dvec3 f = c - glm::dvec3(a);
  double sum = 0.0;
  for (int dz = 0; dz < 2; ++dz)
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const glm::ivec3 q = glm::min(a + glm::ivec3(dx, dy, dz), v.dims - 1);
        const double w = (dx ? f.x : 1 - f.x) * (dy ? f.y : 1 - f.y) * (dz ? f.z : 1 - f.z);
        sum += w * v.at(q.x, q.y, q.z);
      }
  return v.toPhysical(sum);
}

// The stored slices of FOLDER, sorted along their normal.
std::vector<Volume> slicesOf(const std::string& folder) {
  std::vector<Volume> slices;
  for (auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.path().extension() == ".dcm") slices.push_back(importDicom(entry.path().string()));
  std::sort(slices.begin(), slices.end(), [](const Volume& a, const Volume& b) {
    return glm::dot(a.originMm, a.direction[2]) < glm::dot(b.originMm, b.direction[2]);
  });
  return slices;
}

struct Coverage {
  size_t pixels = 0, outside = 0, tissueOutside = 0;
  // |volume - pixel| in physical units at every STRIDE-th pixel of each row and column, for
  // pixels at least EDGE pixels from their slice's border and not on the first or last
  // slice (where the grid's cells reach past the acquired data), and for all others; and
  // for the interior ones at one voxel off along each of V's axes, both ways.
  std::vector<double> interiorError, borderError;
  std::vector<double> shiftedError[6];
};

// Every pixel of every slice file in FOLDER against the straightened volume V.
Coverage coverage(const Volume& v, const std::string& folder, int edge, double tissue, int stride) {
  const std::vector<Volume> slices = slicesOf(folder);
  Coverage out;
  for (size_t k = 0; k < slices.size(); ++k) {
    const Volume& s = slices[k];
    const bool endSlice = k == 0 || k + 1 == slices.size();
    for (int y = 0; y < s.dims.y; ++y)
      for (int x = 0; x < s.dims.x; ++x) {
        const glm::dvec3 p = s.originMm + double(x) * s.spacingMm.x * s.direction[0] +
                             double(y) * s.spacingMm.y * s.direction[1];
        const glm::dvec3 c = indexOf(v, p);
        const double value = s.toPhysical(s.at(x, y, 0));
        ++out.pixels;
        if (!inside(v, c)) {
          ++out.outside;
          out.tissueOutside += value > tissue;
          continue;
        }
        if (x % stride != 0 || y % stride != 0) continue;
        const bool interior =
            !endSlice && x >= edge && y >= edge && x < s.dims.x - edge && y < s.dims.y - edge;
        (interior ? out.interiorError : out.borderError)
            .push_back(std::abs(sampleAt(v, c) - value));
        if (!interior) continue;
        for (int axis = 0; axis < 6; ++axis) {
          glm::dvec3 off = c;
          off[axis / 2] += axis % 2 ? 1.0 : -1.0;
          if (inside(v, off)) out.shiftedError[axis].push_back(std::abs(sampleAt(v, off) - value));
        }
      }
  }
  return out;
}

// Slices of 48 x 48 pixels (2 mm), 16 of them, the table 3 mm a slice; each pixel holds
// 2x + 3y + 5z of its LPS position (mm).
constexpr int kTiltedSize = 48, kSlices = 16;
constexpr double kPixel = 2.0, kAdvance = 3.0, kTiltDeg = 20.0;

double linearValue(const glm::dvec3& p) { return 2 * p.x + 3 * p.y + 5 * p.z; }

// A series of square slices with rows along ROW and columns along COL, slice k at
// ORIGIN + OFFSETS[k] * ADVANCE, pixels holding linearValue of their LPS position.
struct Stack {
  glm::dvec3 row, col, origin, advance;
  std::vector<double> offsets;
};

void writeSeries(const std::string& folder, const Stack& st) {
  for (size_t k = 0; k < st.offsets.size(); ++k) {
    const glm::dvec3 origin = st.origin + st.offsets[k] * st.advance;
    test::TestSlice s;
    s.size = kTiltedSize;
    s.instance = int(k) + 1;
    s.position = {origin.x, origin.y, origin.z};
    s.orientation = {st.row.x, st.row.y, st.row.z, st.col.x, st.col.y, st.col.z};
    s.pixelSpacing = kPixel;
    s.pixel = [=](int i, int j) {
      return int16_t(
          std::lround(linearValue(origin + kPixel * (double(i) * st.row + double(j) * st.col))));
    };
    test::writeTestSlice(folder + "/" + std::to_string(k + 1) + ".dcm", s);
  }
}

std::vector<double> evenOffsets() {
  std::vector<double> d;
  for (int k = 0; k < kSlices; ++k) d.push_back(kAdvance * k);
  return d;
}

// Every pixel inside V, and within 1 HU of V there away from the borders: linear values
// survive bilinear, linear-between-slices and trilinear interpolation exactly; what is
// left is rounding to whole HU twice (stored pixel, resampled voxel).
void expectEveryPixelAtItsValue(const Volume& v, const std::string& folder) {
  const Coverage c = coverage(v, folder, 2, -1e9, 1);
  EXPECT_EQ(c.pixels, size_t(kTiltedSize * kTiltedSize * kSlices));
  EXPECT_EQ(c.outside, 0u);
  EXPECT_LE(quantile(c.interiorError, 1.0), 1.0);
  EXPECT_GT(c.interiorError.size(), c.borderError.size());
}

TEST(DicomTiltCoverage, SyntheticTiltKeepsEveryPixelAtItsValue) {
  test::TempDir dir;
  const double t = glm::radians(kTiltDeg);
  writeSeries(
      dir.path().string(),
      {{1, 0, 0}, {0, std::cos(t), -std::sin(t)}, {-40.0, -50.0, 10.0}, {0, 0, 1}, evenOffsets()});
  Volume v = importDicom(dir.path().string());
  ASSERT_TRUE(test::anyContains(v.warnings, "gantry tilt of 20.0 degrees"));
  // Straightened: axial axes; along z from the lowest pixel row of the first slice
  // (10 - 47 * 2 * sin 20 deg) to the top row of the last (10 + 15 * 3).
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
  const double low = 10.0 - (kTiltedSize - 1) * kPixel * std::sin(t);
  EXPECT_NEAR(v.originMm.z, low, 1e-6);
  EXPECT_NEAR(v.originMm.z + (v.dims.z - 1) * v.spacingMm.z, 10.0 + kAdvance * (kSlices - 1), 1e-6);
  EXPECT_TRUE(test::anyContains(v.warnings, "outside the acquired slices and is filled with air"));
  expectEveryPixelAtItsValue(v, dir.path().string());
}

// The other resampled stacks: a patient on the side (decubitus: rows along posterior,
// columns towards the feet) scanned with a tilted gantry, and an oblique stack with uneven
// gaps and no tilt (resampled along its own normal).
TEST(DicomTiltCoverage, DecubitusTiltAndUnevenObliqueStacksKeepEveryPixel) {
  {
    test::TempDir dir;
    const double t = glm::radians(12.0);
    writeSeries(
        dir.path().string(),
        {{0, 1, 0}, {std::sin(t), 0, -std::cos(t)}, {30.0, -20.0, 40.0}, {1, 0, 0}, evenOffsets()});
    Volume v = importDicom(dir.path().string());
    ASSERT_TRUE(test::anyContains(v.warnings, "gantry tilt of 12.0 degrees"));
    expectEveryPixelAtItsValue(v, dir.path().string());
  }
  {
    test::TempDir dir;
    const glm::dvec3 row = glm::normalize(glm::dvec3(1, 0.3, 0));
    const glm::dvec3 col = glm::normalize(glm::cross(glm::dvec3(0.2, -0.1, 1), row));
    std::vector<double> offsets = evenOffsets();
    for (size_t k = 5; k < offsets.size(); ++k) offsets[k] += 1.7;  // one gap of 4.7 mm
    for (size_t k = 11; k < offsets.size(); ++k) offsets[k] += 0.9;
    writeSeries(dir.path().string(),
                {row, col, {-10.0, 5.0, -30.0}, glm::cross(row, col), offsets});
    Volume v = importDicom(dir.path().string());
    ASSERT_TRUE(test::anyContains(v.warnings, "uneven slice gaps"));
    EXPECT_FALSE(test::anyContains(v.warnings, "gantry tilt"));
    expectEveryPixelAtItsValue(v, dir.path().string());
  }
}

// Interpolation makes each value of V a weighted mean of stored pixels near it: the value
// at P is a mean of its cell's corners (no farther than the cell's diagonal), each a mean of
// the pixels around its projection onto the two slices that bracket it along the normal.
// So V at P lies within the stored values of those slices, in windows around P's projection
// as wide as the diagonal plus one pixel. Counts the sampled pixels of interior slices
// (every STRIDE-th, away from the slices' borders) where it does not, beyond rounding.
struct Bounded {
  size_t checked = 0, outOfRange = 0;
};

Bounded withinNeighbourValues(const Volume& v, const std::vector<Volume>& slices, int stride) {
  const glm::dvec3 n = slices[0].direction[2];
  std::vector<double> d;
  for (const Volume& s : slices) d.push_back(glm::dot(s.originMm, n));
  const double sx = slices[0].spacingMm.x, sy = slices[0].spacingMm.y;
  const double diagonal = glm::length(v.spacingMm);
  const int w = int(std::ceil(diagonal / std::min(sx, sy))) + 1;
  Bounded out;
  for (size_t k = 1; k + 1 < slices.size(); ++k) {
    // Slices that can bracket a point within DIAGONAL of slice K's plane.
    size_t first = k, last = k;
    while (first > 0 && d[first] > d[k] - diagonal) --first;
    while (last + 1 < slices.size() && d[last] < d[k] + diagonal) ++last;
    const Volume& s = slices[k];
    for (int y = w; y < s.dims.y - w; y += stride)
      for (int x = w; x < s.dims.x - w; x += stride) {
        const glm::dvec3 p =
            s.originMm + double(x) * sx * s.direction[0] + double(y) * sy * s.direction[1];
        double lo = 1e300, hi = -1e300;
        for (size_t b = first; b <= last; ++b) {
          const Volume& t = slices[b];
          const glm::dvec3 r = p - t.originMm;
          const int u = int(std::lround(glm::dot(r, t.direction[0]) / sx));
          const int q = int(std::lround(glm::dot(r, t.direction[1]) / sy));
          for (int yy = std::max(0, q - w); yy <= std::min(t.dims.y - 1, q + w); ++yy)
            for (int xx = std::max(0, u - w); xx <= std::min(t.dims.x - 1, u + w); ++xx) {
              const double value = t.toPhysical(t.at(xx, yy, 0));
              lo = std::min(lo, value);
              hi = std::max(hi, value);
            }
        }
        const double got = sampleAt(v, indexOf(v, p));
        ++out.checked;
        out.outOfRange += got < lo - 1.0 || got > hi + 1.0;  // 1: whole-HU rounding
      }
  }
  return out;
}

// The shared tilted CTs: every pixel inside the straightened grid (tissue pixels above
// -500 HU were the ones lost before), and the values there within interpolation's reach.
void expectRealTiltCovered(const std::string& rel) {
  Volume v = importDicom(test::dicomPath(rel));
  ASSERT_TRUE(test::anyContains(v.warnings, "gantry tilt"));
  const Coverage c = coverage(v, test::dicomPath(rel), 2, -500.0, 5);
  EXPECT_EQ(c.outside, 0u) << c.tissueOutside << " tissue pixels outside";
  EXPECT_EQ(c.tissueOutside, 0u);
  // In place: the pixels match the volume where they lie better than one voxel off.
  const double median = quantile(c.interiorError, 0.5);
  for (const auto& shifted : c.shiftedError) EXPECT_LT(median, quantile(shifted, 0.5)) << rel;
  const Bounded b = withinNeighbourValues(v, slicesOf(test::dicomPath(rel)), 9);
  EXPECT_GT(b.checked, 5000u);
  EXPECT_EQ(b.outOfRange, 0u) << "of " << b.checked;
  std::printf(
      "%s: %zu pixels, %zu tissue outside; interior |error| median %.1f HU (one "
      "voxel off: %.1f to %.1f), 99th percentile %.1f; %zu of %zu sampled outside "
      "their neighbours' range\n",
      rel.c_str(), c.pixels, c.tissueOutside, median, quantile(c.shiftedError[0], 0.5),
      quantile(c.shiftedError[5], 0.5), quantile(c.interiorError, 0.99), b.outOfRange, b.checked);
}

TEST(DicomTiltCoverage, GeTiltedHeadKeepsEveryPixel) { expectRealTiltCovered("ct-ge-tilt"); }

TEST(DicomTiltCoverage, TiltFoundFromPositionsKeepsEveryPixel) {
  expectRealTiltCovered("edge-cases/failing/gantrytilting/001");
}

}  // namespace
}  // namespace voxray
