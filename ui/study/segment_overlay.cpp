#include "segment_overlay.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace voxray {

std::vector<int64_t> planeVoxels(const VoxelGrid& grid, const PlaneGrid& g) {
  std::vector<int64_t> out(size_t(std::max(0, g.size.x)) * size_t(std::max(0, g.size.y)), -1);
  // The index moves linearly across the plane: one step per pixel along x and along y.
  const glm::dvec3 o = grid.toIndex(g.originMm);
  const glm::dvec3 du = grid.toIndex(g.originMm + g.uDir * g.spacingMm.x) - o;
  const glm::dvec3 dv = grid.toIndex(g.originMm + g.vDir * g.spacingMm.y) - o;
  for (int y = 0; y < g.size.y; ++y)
    for (int x = 0; x < g.size.x; ++x) {
      const glm::dvec3 p = o + double(x) * du + double(y) * dv;
      const glm::ivec3 i(int(std::floor(p.x + 0.5)), int(std::floor(p.y + 0.5)),
                         int(std::floor(p.z + 0.5)));
      if (glm::any(glm::lessThan(i, glm::ivec3(0))) ||
          glm::any(glm::greaterThanEqual(i, grid.dims)))
        continue;
      out[size_t(y) * size_t(g.size.x) + size_t(x)] = int64_t(grid.index(i.x, i.y, i.z));
    }
  return out;
}

namespace {

uint8_t byte(float f) { return uint8_t(std::lround(std::clamp(f, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

Image segmentOverlay(const Segmentation& s, const PlaneGrid& g) {
  Image out(g.size.x, g.size.y);
  if (s.labels.size() != s.grid.voxelCount() || s.segments.empty()) return out;
  const auto voxels = planeVoxels(s.grid, g);
  std::vector<uint8_t> labels(voxels.size(), 0);
  for (size_t i = 0; i < voxels.size(); ++i)
    if (voxels[i] >= 0) labels[i] = s.labels[size_t(voxels[i])];
  // Colours by label: only visible segments are drawn.
  struct Look {
    bool shown = false;
    uint8_t r = 0, g = 0, b = 0, fill = 0, line = 0;
  };
  std::array<Look, 256> look{};
  for (const Segment& seg : s.segments)
    if (seg.visible && seg.opacity > 0.0f)
      look[seg.label] = {true,
                         byte(seg.colour.r),
                         byte(seg.colour.g),
                         byte(seg.colour.b),
                         byte(seg.opacity * kSegmentFillShare),
                         byte(seg.opacity)};
  const int w = g.size.x, h = g.size.y;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t l = labels[size_t(y) * size_t(w) + size_t(x)];
      if (!l || !look[l].shown) continue;
      const auto other = [&](int xx, int yy) {
        return xx >= 0 && yy >= 0 && xx < w && yy < h &&
               labels[size_t(yy) * size_t(w) + size_t(xx)] != l;
      };
      const bool edge = other(x - 1, y) || other(x + 1, y) || other(x, y - 1) || other(x, y + 1);
      uint8_t* p = out.pixel(x, y);
      p[0] = look[l].r;
      p[1] = look[l].g;
      p[2] = look[l].b;
      p[3] = edge ? look[l].line : look[l].fill;
    }
  return out;
}

Image thresholdOverlay(const Volume& v, const PlaneGrid& g, HuRange range, glm::vec3 colour,
                       float alpha) {
  Image out(g.size.x, g.size.y);
  const StoredRange r = storedRangeOf(v, range);
  if (r.empty()) return out;
  const auto voxels = planeVoxels(gridOf(v), g);
  for (size_t i = 0; i < voxels.size(); ++i) {
    if (voxels[i] < 0 || !r.contains(v.voxels[size_t(voxels[i])])) continue;
    uint8_t* p = &out.rgba[i * 4];
    p[0] = byte(colour.r);
    p[1] = byte(colour.g);
    p[2] = byte(colour.b);
    p[3] = byte(alpha);
  }
  return out;
}

}  // namespace voxray
