// The surface of an analytic sphere against its formulas (issue 34's accuracy goals).
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "mesh_test_scenes.h"
#include "voxray/io/error.h"
#include "voxray/io/segment_mesh.h"

namespace voxray {
namespace {

class SphereSurface : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scene_ = new Segmentation(sphereSegmentation(kRadius, kSpacing));
    surface_ = new SegmentSurface(makeSurface(*scene_, 1));
  }
  static void TearDownTestSuite() {
    delete surface_;
    delete scene_;
  }
  static constexpr double kRadius = 40.0, kSpacing = 0.7;
  static Segmentation* scene_;
  static SegmentSurface* surface_;
};
Segmentation* SphereSurface::scene_ = nullptr;
SegmentSurface* SphereSurface::surface_ = nullptr;

// 1 %: issue 34's goal. The voxelised sphere itself is within ~0.1 % (a 0.7 mm staircase on
// a 40 mm radius); smoothing shrinks it by a few hundredths of a voxel.
TEST_F(SphereSurface, VolumeAndAreaWithinOnePercent) {
  const double volume = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;
  const double area = 4.0 * std::numbers::pi * kRadius * kRadius;
  EXPECT_NEAR(surface_->volumeMm3, volume, 0.01 * volume);
  EXPECT_NEAR(surface_->areaMm2, area, 0.01 * area);
  // Below the default 500k: not simplified, so this is flying edges + smoothing alone.
  EXPECT_LT(surface_->triangleCount(), 500000u);
  EXPECT_GT(surface_->triangleCount(), 50000u);
}

TEST_F(SphereSurface, IsClosedAndManifold) {
  const EdgeCount e = countEdges(*surface_);
  EXPECT_EQ(e.boundary, 0u);
  EXPECT_EQ(e.nonManifold, 0u);
  EXPECT_EQ(e.misoriented, 0u);
  // Euler: a closed surface of genus 0 has V - E + F = 2.
  EXPECT_EQ(
      int64_t(surface_->vertices.size()) - int64_t(e.edges) + int64_t(surface_->triangleCount()),
      2);
}

// Half a voxel: issue 34's bound. Vertices start on voxel-face midpoints (within half a
// voxel of the true surface) and smoothing moves them towards it.
TEST_F(SphereSurface, VerticesLieWithinHalfAVoxelOfTheSphere) {
  const glm::dvec3 centre = sphereCentre(*scene_);
  double worst = 0;
  for (const auto& v : surface_->vertices)
    worst = std::max(worst, std::abs(glm::length(glm::dvec3(v) - centre) - kRadius));
  EXPECT_LT(worst, 0.5 * kSpacing);
}

TEST_F(SphereSurface, TrianglesFaceOutwards) {
  const glm::dvec3 centre = sphereCentre(*scene_);
  size_t inward = 0;
  const auto& ix = surface_->indices;
  for (size_t i = 0; i < ix.size(); i += 3) {
    const glm::dvec3 a = surface_->vertices[ix[i]], b = surface_->vertices[ix[i + 1]],
                     c = surface_->vertices[ix[i + 2]];
    if (glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0 - centre) <= 0) ++inward;
  }
  EXPECT_EQ(inward, 0u);
}

// Simplified (meshoptimizer) to a quarter of its triangles, the bone case's ratio, it still
// holds volume and area within 1 % and stays closed. Edge collapses may pinch it (edges in 4
// triangles), which is why preserveTopology exists; counted, not required to be 0.
TEST_F(SphereSurface, SimplifiedKeepsVolumeAndAreaAndStaysClosed) {
  SurfaceOptions o;
  o.targetTriangles = surface_->triangleCount() / 4;
  const SegmentSurface simplified = makeSurface(*scene_, 1, o);
  EXPECT_LE(simplified.triangleCount(), o.targetTriangles);
  EXPECT_GT(simplified.triangleCount(), o.targetTriangles * 9 / 10);
  const double volume = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;
  const double area = 4.0 * std::numbers::pi * kRadius * kRadius;
  EXPECT_NEAR(simplified.volumeMm3, volume, 0.01 * volume);
  EXPECT_NEAR(simplified.areaMm2, area, 0.01 * area);
  const EdgeCount e = countEdges(simplified);
  EXPECT_EQ(e.boundary, 0u);
  EXPECT_EQ(e.misoriented, 0u);
  // Pinches stay rare (4 of ~46k edges when written; 0.6 % on the noisy bone of the bench).
  EXPECT_LT(e.nonManifold * 1000, e.edges);
  std::printf("meshoptimizer: %zu of %zu triangles, %zu non-manifold edges\n",
              simplified.triangleCount(), surface_->triangleCount(), e.nonManifold);
}

// DecimatePro with PreserveTopology: closed and manifold, though it may stop short of its target.
TEST_F(SphereSurface, TopologyPreservingDecimationIsClosedManifold) {
  SurfaceOptions o;
  o.targetTriangles = surface_->triangleCount() / 4;
  o.preserveTopology = true;
  const SegmentSurface decimated = makeSurface(*scene_, 1, o);
  EXPECT_LT(decimated.triangleCount(), surface_->triangleCount() / 2);
  const EdgeCount e = countEdges(decimated);
  EXPECT_TRUE(e.closedManifold()) << e.boundary << " boundary, " << e.nonManifold
                                  << " non-manifold edges";
  const double volume = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius;
  EXPECT_NEAR(decimated.volumeMm3, volume, 0.01 * volume);
  std::printf("DecimatePro: %zu of %zu triangles\n", decimated.triangleCount(),
              surface_->triangleCount());
}

// Without smoothing, flying edges at 0.5 cuts every edge between an inside and an outside
// voxel centre halfway: a 4x4x4-voxel box with its 12 edges and 8 corners bevelled by half a
// voxel. In voxels: 27 inner cells + 6 faces x 9 half cells + 12 edges x 3 cells x 1/8 + 8
// corner tetrahedra of 1/48 = 58 2/3, times the voxel's 0.5 x 1 x 2 = 1 mm3.
TEST(SegmentSurface, UnsmoothedBoxHasTheBevelledBoxsVolume) {
  Segmentation s;
  s.grid.dims = {6, 6, 6};
  s.grid.spacingMm = {0.5, 1.0, 2.0};
  s.labels.assign(s.grid.voxelCount(), 0);
  for (int z = 1; z < 5; ++z)
    for (int y = 1; y < 5; ++y)
      for (int x = 1; x < 5; ++x) s.labels[s.grid.index(x, y, z)] = 2;
  s.segments.push_back(Segment{});
  s.segments.back().label = 2;
  SurfaceOptions o;
  o.smoothingIterations = 0;
  const SegmentSurface surface = makeSurface(s, 2, o);
  EXPECT_NEAR(surface.volumeMm3, 58.0 + 2.0 / 3.0, 1e-4);
  EXPECT_TRUE(countEdges(surface).closedManifold());
}

// A segment that runs out of the grid (here: a whole 3x3x3 grid) is closed at the grid's faces:
// the cropped copy has a ring of empty voxels around it. Unsmoothed, counted as for the box
// above: 8 inner cells + 6 faces x 4 half cells + 12 edges x 2 x 1/8 + 8 x 1/48 = 23 1/6 voxels.
TEST(SegmentSurface, SegmentFillingTheGridIsClosed) {
  Segmentation s;
  s.grid.dims = {3, 3, 3};
  s.labels.assign(s.grid.voxelCount(), 4);
  s.segments.push_back(Segment{});
  s.segments.back().label = 4;
  SurfaceOptions o;
  o.smoothingIterations = 0;
  const SegmentSurface surface = makeSurface(s, 4, o);
  EXPECT_TRUE(countEdges(surface).closedManifold());
  EXPECT_NEAR(surface.volumeMm3, 23.0 + 1.0 / 6.0, 1e-4);
}

TEST(SegmentSurface, EmptySegmentIsRefusedByName) {
  Segmentation s = sphereSegmentation(5.0, 1.0);
  Segment empty;
  empty.label = 7;
  empty.name = "Liver";
  s.segments.push_back(empty);
  try {
    makeSurface(s, 7);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    EXPECT_NE(std::string(e.what()).find("\"Liver\" (label 7) has no voxels"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(makeSurface(s, 9), Error);  // no segment 9
}

}  // namespace
}  // namespace voxray
