#include "macro_cells.h"

#include <algorithm>

#include "voxray/io/parallel.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

void cellSlab(const Volume& v, MacroCells& m, int cz) {
  const glm::ivec3 d = v.dims;
  auto span = [](int c, int n) {
    return glm::ivec2(std::max(c * kCellSize - 1, 0), std::min((c + 1) * kCellSize, n - 1));
  };
  glm::ivec2 z = span(cz, d.z);
  for (int cy = 0; cy < m.dims.y; ++cy) {
    glm::ivec2 y = span(cy, d.y);
    for (int cx = 0; cx < m.dims.x; ++cx) {
      glm::ivec2 x = span(cx, d.x);
      int16_t lo = INT16_MAX, hi = INT16_MIN;
      for (int k = z.x; k <= z.y; ++k)
        for (int j = y.x; j <= y.y; ++j) {
          const int16_t* row = &v.voxels[v.index(x.x, j, k)];
          auto [a, b] = std::minmax_element(row, row + (x.y - x.x + 1));
          lo = std::min(lo, *a);
          hi = std::max(hi, *b);
        }
      size_t cell = (size_t(cz) * size_t(m.dims.y) + size_t(cy)) * size_t(m.dims.x) + size_t(cx);
      m.minMax[cell * 2] = lo;
      m.minMax[cell * 2 + 1] = hi;
    }
  }
}

}  // namespace

MacroCells computeMacroCells(const Volume& v) {
  MacroCells m;
  m.dims = (v.dims + (kCellSize - 1)) / kCellSize;
  size_t cells = size_t(m.dims.x) * size_t(m.dims.y) * size_t(m.dims.z);
  m.minMax.resize(cells * 2);
  // One slab of cells along z per index: every slab costs the same, and each writes only
  // its own cells.
  parallelFor(size_t(m.dims.z), [&](size_t cz) { cellSlab(v, m, int(cz)); });
  return m;
}

}  // namespace voxray
