// The surface fields (engine/src/surface_field.h): an edit inside a field's box filters it again
// around the edit to the very bytes a whole build gives; one that grows the segment out of its
// box asks for a build. Times of a CT-sized bone's field printed (shared machine), not asserted.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "surface_field.h"
#include "voxray/io/segmentation.h"

namespace voxray {
namespace {

Segmentation grid(glm::ivec3 dims) {
  Segmentation s;
  s.grid.dims = dims;
  s.labels.assign(s.grid.voxelCount(), 0);
  return s;
}

// Label L on voxels within R of C (voxels), and within the shell's inner radius RI none.
void shell(Segmentation& s, glm::dvec3 c, double r, double ri, uint8_t l) {
  const glm::ivec3 d = s.grid.dims;
  for (int z = 0; z < d.z; ++z)
    for (int y = 0; y < d.y; ++y)
      for (int x = 0; x < d.x; ++x) {
        const double e = glm::length(glm::dvec3(x, y, z) - c);
        if (e <= r && e >= ri) s.labels[s.grid.index(x, y, z)] = l;
      }
}

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

TEST(SurfaceField, AnEditInsideItsBoxGivesTheBytesOfAWholeBuild) {
  Segmentation s = grid({40, 36, 30});
  shell(s, {20, 18, 15}, 12.0, 0.0, 1);
  shell(s, {5, 5, 5}, 3.0, 0.0, 2);  // another segment, in the corner
  SurfaceField f = buildSurfaceField(s, 1);
  ASSERT_FALSE(f.empty());
  EXPECT_EQ(f.coreLo, glm::ivec3(8, 6, 3));
  EXPECT_EQ(f.coreHi, glm::ivec3(32, 30, 27));
  // A hole near the middle, then a dab of the other segment over the sphere's edge.
  for (int z = 13; z <= 17; ++z)
    for (int y = 16; y <= 20; ++y)
      for (int x = 18; x <= 22; ++x) s.labels[s.grid.index(x, y, z)] = 0;
  ASSERT_TRUE(updateSurfaceField(f, s, {18, 16, 13}, {22, 20, 17}));
  for (int x = 27; x <= 30; ++x) s.labels[s.grid.index(x, 18, 15)] = 2;  // x 32 stays 1
  ASSERT_TRUE(surfaceFieldTouched(f, s, {27, 18, 15}, {30, 18, 15}));
  ASSERT_TRUE(updateSurfaceField(f, s, {27, 18, 15}, {30, 18, 15}));
  const SurfaceField whole = buildSurfaceField(s, 1);
  ASSERT_EQ(f.lo, whole.lo);  // the segment's box is as before the edits
  ASSERT_EQ(f.dims, whole.dims);
  EXPECT_EQ(f.values, whole.values);
  EXPECT_EQ(f.blocks, whole.blocks);
  // Grown out of its box: a build is needed, the field stays as it was.
  s.labels[s.grid.index(36, 18, 15)] = 1;
  const auto before = f.values;
  EXPECT_FALSE(updateSurfaceField(f, s, {36, 18, 15}, {36, 18, 15}));
  EXPECT_EQ(f.values, before);
  // Far from its padded box and without its label: not its edit.
  EXPECT_FALSE(surfaceFieldTouched(f, s, {0, 0, 0}, {1, 1, 1}));
}

TEST(SurfaceField, BuildAndDabTimesOnACtSizedBone) {
  // A skull-like shell, 8 voxels thick, in a 512 x 512 x 400 label map.
  Segmentation s = grid({512, 512, 400});
  shell(s, {256, 256, 200}, 180.0, 172.0, 1);
  auto t0 = std::chrono::steady_clock::now();
  SurfaceField f = buildSurfaceField(s, 1);
  const double buildMs = msSince(t0);
  for (int z = 195; z <= 205; ++z)
    for (int y = 420; y <= 430; ++y)
      for (int x = 251; x <= 261; ++x) s.labels[s.grid.index(x, y, z)] = 1;
  t0 = std::chrono::steady_clock::now();
  ASSERT_TRUE(updateSurfaceField(f, s, {251, 420, 195}, {261, 430, 205}));
  const double dabMs = msSince(t0);
  std::printf("512x512x400 shell (%zu field bytes): whole build %.0f ms, an 11-voxel dab %.1f ms\n",
              f.values.size(), buildMs, dabMs);
  SUCCEED();
}

}  // namespace
}  // namespace voxray
