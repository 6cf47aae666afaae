// The macro cells' min/max (empty_space's tables) against a brute-force scan of each cell's
// voxels with its one-voxel apron, on random voxels and dims that are not multiples of the
// cell size (issue 38 sped up their computation; it must stay exact).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "macro_cells.h"
#include "voxray/io/volume.h"

namespace voxray {
namespace {

TEST(MacroCells, EqualABruteForceScanWithApron) {
  for (const glm::ivec3 n : {glm::ivec3(13, 9, 7), glm::ivec3(4, 4, 4), glm::ivec3(1, 17, 6)}) {
    Volume v;
    v.dims = n;
    v.voxels.resize(v.voxelCount());
    std::mt19937 rng(n.x * 100 + n.y * 10 + n.z);
    std::uniform_int_distribution<int> value(-32768, 32767);
    for (auto& x : v.voxels) x = int16_t(value(rng));
    const MacroCells m = computeMacroCells(v);
    ASSERT_EQ(m.dims, (n + kCellSize - 1) / kCellSize);
    for (int cz = 0; cz < m.dims.z; ++cz)
      for (int cy = 0; cy < m.dims.y; ++cy)
        for (int cx = 0; cx < m.dims.x; ++cx) {
          int lo = 32767, hi = -32768;
          for (int z = std::max(cz * kCellSize - 1, 0);
               z <= std::min((cz + 1) * kCellSize, n.z - 1); ++z)
            for (int y = std::max(cy * kCellSize - 1, 0);
                 y <= std::min((cy + 1) * kCellSize, n.y - 1); ++y)
              for (int x = std::max(cx * kCellSize - 1, 0);
                   x <= std::min((cx + 1) * kCellSize, n.x - 1); ++x) {
                lo = std::min<int>(lo, v.at(x, y, z));
                hi = std::max<int>(hi, v.at(x, y, z));
              }
          const size_t c =
              (size_t(cz) * size_t(m.dims.y) + size_t(cy)) * size_t(m.dims.x) + size_t(cx);
          ASSERT_EQ(m.minMax[2 * c], lo) << cx << "," << cy << "," << cz;
          ASSERT_EQ(m.minMax[2 * c + 1], hi) << cx << "," << cy << "," << cz;
        }
  }
}

}  // namespace
}  // namespace voxray
