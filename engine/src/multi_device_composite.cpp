#include "multi_device_composite.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "rgba8.h"
#include "voxray/io/parallel.h"

namespace voxray {

namespace {

constexpr int kMaxParts = 64;

}  // namespace

void compositeParts(Mode mode, const std::vector<const PartImage*>& parts, int width, int height,
                    glm::vec3 background, float earlyTermination, Image& out) {
  out.width = width;
  out.height = height;
  out.rgba.resize(size_t(width) * size_t(height) * 4);
  const size_t n = std::min(parts.size(), size_t(kMaxParts));
  std::array<const float*, kMaxParts> colour{}, order{};
  for (size_t k = 0; k < n; ++k) {
    colour[k] = parts[k]->colour;
    order[k] = parts[k]->order;
  }
  const int bandRows = 32;  // bands of rows, a few per thread
  parallelFor(size_t((height + bandRows - 1) / bandRows), [&](size_t band) {
    std::array<size_t, kMaxParts> idx{};
    const int y0 = int(band) * bandRows, y1 = std::min(height, y0 + bandRows);
    for (size_t px = size_t(y0) * size_t(width); px < size_t(y1) * size_t(width); ++px) {
      glm::vec3 rgb = background;
      if (mode == Mode::Dvr) {
        // Front to back: the parts by the index their range starts at along this ray
        // (insertion sort: a handful of parts).
        for (size_t k = 0; k < n; ++k) {
          size_t j = k;
          for (; j > 0 && order[idx[j - 1]][px] > order[k][px]; --j) idx[j] = idx[j - 1];
          idx[j] = k;
        }
        glm::vec3 acc(0.0f);
        float alpha = 0.0f;
        for (size_t k = 0; k < n && alpha < earlyTermination; ++k) {
          const float* c = colour[idx[k]] + px * 4;
          acc += (1.0f - alpha) * glm::vec3(c[0], c[1], c[2]);
          alpha += (1.0f - alpha) * c[3];
        }
        rgb = acc + (1.0f - alpha) * background;
      } else if (mode == Mode::Iso) {
        float best = 0.0f;
        const float* hit = nullptr;
        for (size_t k = 0; k < n; ++k)
          if (colour[k][px * 4 + 3] > 0.0f && (!hit || order[k][px] < best)) {
            hit = colour[k] + px * 4;
            best = order[k][px];
          }
        if (hit) rgb = glm::vec3(hit[0], hit[1], hit[2]);
      } else {
        float grey = -1.0f;
        for (size_t k = 0; k < n; ++k)
          if (colour[k][px * 4 + 3] > 0.0f) grey = std::max(grey, colour[k][px * 4]);
        if (grey >= 0.0f) rgb = glm::vec3(grey);
      }
      uint8_t* o = &out.rgba[px * 4];
      o[0] = toRgba8Byte(rgb.x);
      o[1] = toRgba8Byte(rgb.y);
      o[2] = toRgba8Byte(rgb.z);
      o[3] = 255;
    }
  });
}

}  // namespace voxray
