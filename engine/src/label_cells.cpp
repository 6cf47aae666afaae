#include "label_cells.h"

#include <algorithm>

#include "macro_cells.h"
#include "voxray/io/parallel.h"

namespace voxray {

namespace {

void cellRange(LabelCells& m, const Segmentation& s, glm::ivec3 c0, glm::ivec3 c1) {
  const glm::ivec3 d = s.grid.dims;
  auto span = [](int c, int n) {
    return glm::ivec2(std::max(c * kCellSize - 1, 0), std::min((c + 1) * kCellSize, n - 1));
  };
  parallelFor(size_t(c1.z - c0.z + 1), [&](size_t iz) {
    const int cz = c0.z + int(iz);
    const glm::ivec2 z = span(cz, d.z);
    for (int cy = c0.y; cy <= c1.y; ++cy) {
      const glm::ivec2 y = span(cy, d.y);
      for (int cx = c0.x; cx <= c1.x; ++cx) {
        const glm::ivec2 x = span(cx, d.x);
        std::array<uint64_t, 4> bits{};
        for (int k = z.x; k <= z.y; ++k)
          for (int j = y.x; j <= y.y; ++j) {
            const uint8_t* row = &s.labels[s.grid.index(x.x, j, k)];
            for (int i = 0; i <= x.y - x.x; ++i) bits[row[i] >> 6] |= uint64_t(1) << (row[i] & 63);
          }
        m.present[(size_t(cz) * size_t(m.dims.y) + size_t(cy)) * size_t(m.dims.x) + size_t(cx)] =
            bits;
      }
    }
  });
}

}  // namespace

LabelCells computeLabelCells(const Segmentation& s) {
  LabelCells m;
  m.dims = (s.grid.dims + (kCellSize - 1)) / kCellSize;
  m.present.assign(size_t(m.dims.x) * size_t(m.dims.y) * size_t(m.dims.z), {});
  if (m.present.empty()) return m;
  cellRange(m, s, glm::ivec3(0), m.dims - 1);
  return m;
}

void updateLabelCells(LabelCells& m, const Segmentation& s, glm::ivec3 lo, glm::ivec3 hi) {
  // Cell c's span reaches voxels kCellSize c - 1 ... kCellSize c + kCellSize.
  glm::ivec3 c0 = glm::max((lo - kCellSize) / kCellSize - 1, glm::ivec3(0));
  glm::ivec3 c1 = glm::min((hi + 1) / kCellSize, m.dims - 1);
  if (glm::any(glm::greaterThan(c0, c1))) return;
  cellRange(m, s, c0, c1);
}

std::vector<uint8_t> cellsShown(const LabelCells& m, const std::vector<glm::vec4>& table) {
  std::array<uint64_t, 4> shown{};
  for (int l = 0; l < 256; ++l)
    if (table[size_t(2 * l + 1)].x > 0.0f) shown[size_t(l >> 6)] |= uint64_t(1) << (l & 63);
  std::vector<uint8_t> out(m.present.size());
  for (size_t c = 0; c < out.size(); ++c) {
    const auto& p = m.present[c];
    out[c] = ((p[0] & shown[0]) | (p[1] & shown[1]) | (p[2] & shown[2]) | (p[3] & shown[3])) != 0;
  }
  return out;
}

}  // namespace voxray
