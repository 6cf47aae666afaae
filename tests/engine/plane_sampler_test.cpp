// samplePlane (engine/include/voxray/engine/plane_sampler.h): the slice views' resampling.
// Values are checked against the analytic value of a linear ramp (which trilinear
// reconstruction reproduces exactly), voxel values, and the stated background.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "voxray/engine/plane_sampler.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

constexpr float kBackground = -5000.0f;

// stored = 3 i + 5 j + 7 k; physical = stored * 0.5 - 100. Anisotropic (0.5, 0.8, 5 mm),
// slices running towards the feet (LPI), origin off zero: every part of the geometry counts.
Volume ramp() {
  Volume v;
  v.dims = {6, 5, 4};
  v.spacingMm = {0.5, 0.8, 5.0};
  v.originMm = {-10.0, 20.0, 30.0};
  v.direction = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1));
  v.slope = 0.5;
  v.intercept = -100.0;
  v.voxels.resize(v.voxelCount());
  for (int k = 0; k < v.dims.z; ++k)
    for (int j = 0; j < v.dims.y; ++j)
      for (int i = 0; i < v.dims.x; ++i)
        v.voxels[v.index(i, j, k)] = int16_t(3 * i + 5 * j + 7 * k);
  return v;
}

double rampValue(const glm::dvec3& voxel) {
  return (3 * voxel.x + 5 * voxel.y + 7 * voxel.z) * 0.5 - 100.0;
}

glm::dvec3 patientMm(const Volume& v, const glm::dvec3& voxel) {
  return v.originMm + v.direction * (voxel * v.spacingMm);
}

// A single-pixel plane at a voxel position.
float sampleAt(const Volume& v, const glm::dvec3& voxel, Interp interp) {
  PlaneGrid g;
  g.originMm = patientMm(v, voxel);
  g.size = {1, 1};
  return samplePlane(v, g, interp, kBackground)[0];
}

}  // namespace

TEST(PlaneSampler, TrilinearOnAnObliquePlaneIsTheAnalyticRamp) {
  const Volume v = ramp();
  PlaneGrid g;
  const glm::dvec3 start(1.3, 1.1, 0.6);  // voxel coordinates
  g.originMm = patientMm(v, start);
  g.uDir = glm::normalize(glm::dvec3(1.0, 0.4, -0.3));
  g.vDir = glm::normalize(glm::cross(g.uDir, glm::dvec3(0.2, -1.0, 0.1)));
  g.spacingMm = {0.3, 0.7};
  g.size = {7, 5};
  const std::vector<float> out = samplePlane(v, g, Interp::Linear, kBackground);
  ASSERT_EQ(out.size(), 35u);
  int inside = 0;
  for (int y = 0; y < g.size.y; ++y)
    for (int x = 0; x < g.size.x; ++x) {
      const glm::dvec3 mm = g.originMm + x * g.spacingMm.x * g.uDir + y * g.spacingMm.y * g.vDir;
      // Orthonormal direction: its transpose is its inverse.
      const glm::dvec3 voxel = glm::transpose(v.direction) * (mm - v.originMm) / v.spacingMm;
      const float got = out[size_t(y * g.size.x + x)];
      if (glm::all(glm::greaterThanEqual(voxel, glm::dvec3(0.0))) &&
          glm::all(glm::lessThanEqual(voxel, glm::dvec3(v.dims - 1)))) {
        EXPECT_NEAR(got, rampValue(voxel), 1e-3) << x << "," << y;
        ++inside;
      }
    }
  EXPECT_GT(inside, 20);  // the plane mostly lies between voxel centres
}

TEST(PlaneSampler, NearestTakesTheClosestVoxel) {
  const Volume v = ramp();
  EXPECT_FLOAT_EQ(sampleAt(v, {2.4, 3.45, 1.2}, Interp::Nearest), rampValue({2, 3, 1}));
  EXPECT_FLOAT_EQ(sampleAt(v, {2.6, 2.55, 1.8}, Interp::Nearest), rampValue({3, 3, 2}));
  // The same points interpolated lie between the voxels.
  EXPECT_NEAR(sampleAt(v, {2.4, 3.45, 1.2}, Interp::Linear), rampValue({2.4, 3.45, 1.2}), 1e-3);
}

TEST(PlaneSampler, APlaneThroughVoxelCentresReproducesTheSlice) {
  Volume v = ramp();
  for (size_t i = 0; i < v.voxels.size(); ++i) v.voxels[i] = int16_t((i * 7919) % 2000 - 1000);
  // Coronal plane through j = 2: x along i, y along k, one voxel per pixel.
  PlaneGrid g;
  g.originMm = patientMm(v, {0, 2, 0});
  g.uDir = v.direction[0];
  g.vDir = v.direction[2];
  g.spacingMm = {v.spacingMm.x, v.spacingMm.z};
  g.size = {v.dims.x, v.dims.z};
  for (Interp interp : {Interp::Linear, Interp::Nearest}) {
    const std::vector<float> out = samplePlane(v, g, interp, kBackground);
    for (int k = 0; k < v.dims.z; ++k)
      for (int i = 0; i < v.dims.x; ++i)
        ASSERT_EQ(out[size_t(k * v.dims.x + i)], float(v.toPhysical(v.at(i, 2, k))))
            << i << "," << k << " " << toString(interp);
  }
}

TEST(PlaneSampler, ThickSlicesRampWithLinearAndStepWithNearest) {
  const Volume v = ramp();
  // Down the 5 mm axis in 1 mm pixels from slice 1 to slice 2: linear moves 7 * 0.2 stored
  // values (0.7 physical) per pixel, nearest jumps once at the half-way point.
  PlaneGrid g;
  g.originMm = patientMm(v, {2, 2, 1});
  g.uDir = v.direction[2];
  g.spacingMm = {1.0, 1.0};
  g.size = {6, 1};
  const std::vector<float> linear = samplePlane(v, g, Interp::Linear, kBackground);
  const std::vector<float> nearest = samplePlane(v, g, Interp::Nearest, kBackground);
  for (int x = 0; x < 6; ++x) {
    EXPECT_NEAR(linear[size_t(x)], rampValue({2, 2, 1 + 0.2 * x}), 1e-4) << x;
    EXPECT_FLOAT_EQ(nearest[size_t(x)], rampValue({2, 2, x < 3 ? 1 : 2})) << x;
  }
}

TEST(PlaneSampler, EdgesClampInsideTheBoxAndTakeTheBackgroundOutside) {
  const Volume v = ramp();
  const glm::dvec3 last = glm::dvec3(v.dims - 1);
  for (Interp interp : {Interp::Linear, Interp::Nearest}) {
    // Between the outer voxel centres and the box faces: the edge voxel, repeated.
    EXPECT_FLOAT_EQ(sampleAt(v, {-0.3, 0, 0}, interp), rampValue({0, 0, 0}));
    EXPECT_FLOAT_EQ(sampleAt(v, last + 0.4, interp), rampValue(last));
    EXPECT_FLOAT_EQ(sampleAt(v, {-0.5, 0, 0}, interp), rampValue({0, 0, 0}));  // on the face
    // Past a face: the background.
    EXPECT_EQ(sampleAt(v, {-0.6, 1, 1}, interp), kBackground);
    EXPECT_EQ(sampleAt(v, {1, 1, last.z + 0.6}, interp), kBackground);
  }
  // An empty grid or volume gives what it asks for, and nothing is read.
  PlaneGrid g;
  g.size = {3, 2};
  EXPECT_EQ(samplePlane(Volume{}, g, Interp::Linear, kBackground),
            std::vector<float>(6, kBackground));
  g.size = {0, 5};
  EXPECT_TRUE(samplePlane(v, g, Interp::Linear, kBackground).empty());
}

}  // namespace voxray

// Slabs (samplePlane with a Slab): a bright or dark line across the slab, means of known
// sets, and the thin plane for a thickness of 0.
namespace voxray {

namespace {

// 12^3 voxels of 1 mm, physical value 100 everywhere but one line along x at (j, k) = (7, 5).
Volume lineVolume(int16_t line) {
  Volume v;
  v.dims = {12, 12, 12};
  v.voxels.assign(v.voxelCount(), 100);
  for (int i = 0; i < v.dims.x; ++i) v.voxels[v.index(i, 7, 5)] = line;
  return v;
}

// A coronal-like plane (x along i, y along k) through j = J, one voxel per pixel.
PlaneGrid planeAcrossJ(const Volume& v, double j) {
  PlaneGrid g;
  g.originMm = {0.0, j, 0.0};
  g.uDir = {1, 0, 0};
  g.vDir = {0, 0, 1};  // uDir x vDir = -y: the slab runs along j
  g.size = {v.dims.x, v.dims.z};
  return g;
}

}  // namespace

TEST(PlaneSampler, SlabMipOfABrightLineIsTheLine) {
  const Volume v = lineVolume(2000);
  // 6 mm around j = 5: samples at j = 2 ... 8, one on the line's voxel centres.
  const std::vector<float> mip =
      samplePlane(v, planeAcrossJ(v, 5.0), Interp::Linear, kBackground, {6.0, SlabMode::Mip});
  EXPECT_EQ(slabSamples(v, {6.0, SlabMode::Mip}), 7);
  for (int k = 0; k < v.dims.z; ++k)
    for (int i = 0; i < v.dims.x; ++i)
      ASSERT_EQ(mip[size_t(k * v.dims.x + i)], k == 5 ? 2000.0f : 100.0f) << i << "," << k;
  // A slab that stops short of the line (j = 2 ... 6) does not see it.
  const std::vector<float> shortOf =
      samplePlane(v, planeAcrossJ(v, 4.0), Interp::Linear, kBackground, {4.0, SlabMode::Mip});
  EXPECT_EQ(*std::max_element(shortOf.begin(), shortOf.end()), 100.0f);
}

TEST(PlaneSampler, SlabMinIpOfADarkLineAndMeanOfALine) {
  const Volume dark = lineVolume(-900);
  const std::vector<float> minip = samplePlane(dark, planeAcrossJ(dark, 6.0), Interp::Linear,
                                               kBackground, {2.0, SlabMode::MinIp});  // j = 5, 6, 7
  for (int i = 0; i < dark.dims.x; ++i) {
    EXPECT_EQ(minip[size_t(5 * dark.dims.x + i)], -900.0f) << i;
    EXPECT_EQ(minip[size_t(4 * dark.dims.x + i)], 100.0f) << i;
  }
  // Mean over 7 samples (j = 4 ... 10), one on the line: (2000 + 6 * 100) / 7.
  const Volume bright = lineVolume(2000);
  const std::vector<float> mean = samplePlane(bright, planeAcrossJ(bright, 7.0), Interp::Linear,
                                              kBackground, {6.0, SlabMode::Mean});
  EXPECT_FLOAT_EQ(mean[size_t(5 * bright.dims.x + 3)], float((2000.0 + 6 * 100.0) / 7.0));
  EXPECT_EQ(mean[size_t(4 * bright.dims.x + 3)], 100.0f);
}

TEST(PlaneSampler, SlabMeanOfARampIsTheRampAtTheCentre) {
  // A linear ramp's mean over samples placed symmetrically about a point is its value there:
  // an oblique slab well inside the volume gives the thin plane's analytic values.
  const Volume v = ramp();
  PlaneGrid g;
  g.originMm = patientMm(v, {2.2, 1.9, 1.6});
  g.uDir = glm::normalize(glm::dvec3(1.0, 1.0, 0.0));
  g.vDir = glm::normalize(glm::dvec3(-1.0, 1.0, 0.5));
  g.vDir = glm::normalize(g.vDir - glm::dot(g.vDir, g.uDir) * g.uDir);
  g.spacingMm = {0.2, 0.2};
  g.size = {3, 3};
  const std::vector<float> mean =
      samplePlane(v, g, Interp::Linear, kBackground, {1.0, SlabMode::Mean});
  const std::vector<float> thin = samplePlane(v, g, Interp::Linear, kBackground);
  for (size_t i = 0; i < mean.size(); ++i) EXPECT_NEAR(mean[i], thin[i], 1e-3) << i;
}

TEST(PlaneSampler, SlabOfZeroIsTheThinPlaneAndModesHaveNames) {
  Volume v = ramp();
  for (size_t i = 0; i < v.voxels.size(); ++i) v.voxels[i] = int16_t((i * 7919) % 2000 - 1000);
  PlaneGrid g;
  g.originMm = patientMm(v, {0.3, 0.2, 0.4});
  g.uDir = glm::normalize(glm::dvec3(1.0, 0.3, 0.0));
  g.vDir = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), g.uDir));
  g.spacingMm = {0.4, 0.4};
  g.size = {9, 7};
  const std::vector<float> thin = samplePlane(v, g, Interp::Linear, kBackground);
  for (SlabMode m : {SlabMode::Mip, SlabMode::MinIp, SlabMode::Mean}) {
    EXPECT_EQ(samplePlane(v, g, Interp::Linear, kBackground, {0.0, m}), thin) << toString(m);
    EXPECT_EQ(parseSlabMode(toString(m)), m);
  }
  EXPECT_EQ(slabSamples(v, {0.0, SlabMode::Mip}), 1);
  EXPECT_EQ(slabSamples(v, {-3.0, SlabMode::Mip}), 1);
  EXPECT_EQ(slabSamples(v, {1.0, SlabMode::Mip}), 3);     // every 0.5 mm: 0, 0.5, 1
  EXPECT_EQ(slabSamples(v, {1e9, SlabMode::Mip}), 4096);  // bounded
  EXPECT_THROW(parseSlabMode("max"), Error);
}

}  // namespace voxray
