#include "path_majorants.h"

#include <algorithm>
#include <cmath>

#include "voxray/io/volume.h"

namespace voxray {

void PathMajorants::setVolume(const Volume& v) {
  dims_ = (v.dims + kPathCell - 1) / kPathCell;
  range_.assign(size_t(dims_.x) * dims_.y * dims_.z, glm::i16vec2(INT16_MAX, INT16_MIN));
  // Each voxel widens the range of every cell whose samples can read it (its own and the
  // neighbours within one voxel).
  for (int z = 0; z < v.dims.z; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x) {
        int16_t s = v.at(x, y, z);
        glm::ivec3 lo = glm::max(glm::ivec3(x - 1, y - 1, z - 1) / kPathCell, glm::ivec3(0));
        glm::ivec3 hi = glm::min(glm::ivec3(x + 1, y + 1, z + 1) / kPathCell, dims_ - 1);
        for (int cz = lo.z; cz <= hi.z; ++cz)
          for (int cy = lo.y; cy <= hi.y; ++cy)
            for (int cx = lo.x; cx <= hi.x; ++cx) {
              glm::i16vec2& r = range_[(size_t(cz) * dims_.y + cy) * dims_.x + cx];
              r.x = std::min(r.x, s);
              r.y = std::max(r.y, s);
            }
      }
  sigma_.clear();
}

const std::vector<float>& PathMajorants::update(const Lut& lut, double referenceStepMm,
                                                double cap) {
  // Opacity as extinction per entry, then a sparse table of maxima for O(1) range queries.
  int n = int(lut.rgba.size());
  std::vector<std::vector<float>> table(1, std::vector<float>(size_t(n)));
  for (int i = 0; i < n; ++i)
    table[0][size_t(i)] =
        float(-std::log1p(-std::clamp(double(lut.rgba[size_t(i)].a), 0.0, cap)) / referenceStepMm);
  for (int k = 1; (1 << k) <= n; ++k) {
    table.emplace_back(size_t(n - (1 << k) + 1));
    for (size_t i = 0; i < table[k].size(); ++i)
      table[k][i] = std::max(table[k - 1][i], table[k - 1][i + (size_t(1) << (k - 1))]);
  }
  auto entry = [&](double stored) {
    double x = (stored - lut.storedMin) * lut.scale;
    return std::clamp(x, 0.0, double(n - 1));
  };
  sigma_.resize(range_.size());
  for (size_t c = 0; c < range_.size(); ++c) {
    // One entry of margin each side: the kernel finds its entry in float.
    int a = std::max(int(std::floor(entry(range_[c].x))) - 1, 0);
    int b = std::min(int(std::ceil(entry(range_[c].y))) + 1, n - 1);
    int k = 0;
    while ((2 << k) <= b - a + 1) ++k;
    // A hair above: the kernel's float extinction of the same entry must not exceed it.
    sigma_[c] = std::max(table[k][size_t(a)], table[k][size_t(b - (1 << k) + 1)]) * 1.00001f;
  }
  return sigma_;
}

}  // namespace voxray
