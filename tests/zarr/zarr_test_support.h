#pragma once
// Volumes and checks shared by the OME-Zarr tests.
#include <cmath>
#include <string>

#include "test_support.h"
#include "voxray/io/ome_zarr.h"

namespace voxray::test {

// Odd sizes (edge chunks, odd pyramid levels), a rotated LPS direction, a non-zero origin and
// HU from -1024 up (negative values, values beyond one byte).
inline Volume zarrTestVolume() {
  Volume v;
  v.dims = {45, 38, 29};
  v.spacingMm = {0.7, 0.8, 1.3};
  v.originMm = {-12.5, 30.25, 101.0};
  // i along P, j along R (-L), k along I (-S): a proper rotation.
  v.direction = glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, -1));
  v.modality = "CT";
  v.voxels.resize(v.voxelCount());
  for (int z = 0; z < v.dims.z; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x)
        v.voxels[v.index(x, y, z)] = int16_t((x * 71 + y * 13 + z * 131) % 3000 - 1024);
  return v;
}

// The 2x2x2 mean of level L-1 at (x, y, z) of level L, averaging what lies inside an odd
// edge; rounded half to even as int16 levels are.
inline double halvedValue(const Volume& from, int x, int y, int z) {
  double sum = 0;
  int n = 0;
  for (int zz = 2 * z; zz < std::min(2 * z + 2, from.dims.z); ++zz)
    for (int yy = 2 * y; yy < std::min(2 * y + 2, from.dims.y); ++yy)
      for (int xx = 2 * x; xx < std::min(2 * x + 2, from.dims.x); ++xx, ++n)
        sum += from.toPhysical(from.at(xx, yy, zz));
  return std::nearbyint(sum / n);
}

// 1e-6 mm: the geometry goes through JSON as 17-digit doubles and one matrix product.
inline void expectNear(const glm::dvec3& a, const glm::dvec3& b, const char* what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-6) << what << " [" << i << "]";
}

}  // namespace voxray::test
