#include "refine_bands.h"

#include <algorithm>
#include <cstring>

namespace voxray {

std::vector<RowBand> refineBands(int width, int height, int maxBands, long bandPixels) {
  if (width <= 0 || height <= 0) return {};
  const long pixels = long(width) * long(height);
  const int units = (height + kRefineBandAlign - 1) / kRefineBandAlign;  // 16-row blocks
  bandPixels = std::max(bandPixels, 1L);
  int count = int((pixels + bandPixels - 1) / bandPixels);
  count = std::clamp(count, 1, std::clamp(maxBands, 1, units));
  // Top to bottom, block counts differing by at most one.
  std::vector<RowBand> byRow;
  for (int i = 0, at = 0; i < count; ++i) {
    const int blocks = units / count + (i < units % count ? 1 : 0);
    const int y1 = std::min(height, (at + blocks) * kRefineBandAlign);
    byRow.push_back({at * kRefineBandAlign, y1});
    at += blocks;
  }
  // The middle first, then below, above, below ... (for an even count, the upper middle).
  std::vector<RowBand> out;
  const int mid = (count - 1) / 2;
  out.push_back(byRow[size_t(mid)]);
  for (int d = 1; int(out.size()) < count; ++d) {
    if (mid + d < count) out.push_back(byRow[size_t(mid + d)]);
    if (mid - d >= 0) out.push_back(byRow[size_t(mid - d)]);
  }
  return out;
}

std::vector<RowBand> viewFrameBands(const RenderParams& p, bool interactive) {
  if (interactive || p.lighting == Lighting::Cinematic) return {};
  return refineBands(p.width, p.height);
}

Image upscaleNearest(const Image& src, int width, int height) {
  if (src.width == width && src.height == height) return src;
  Image out(width, height);
  if (src.width <= 0 || src.height <= 0) {
    for (size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = 255;
    return out;
  }
  for (int y = 0; y < height; ++y) {
    // Pixel centres: destination (y + 0.5) / height of the source's height.
    const int sy = std::min(src.height - 1, int((2L * y + 1) * src.height / (2L * height)));
    for (int x = 0; x < width; ++x) {
      const int sx = std::min(src.width - 1, int((2L * x + 1) * src.width / (2L * width)));
      std::memcpy(out.pixel(x, y), src.pixel(sx, sy), 4);
    }
  }
  return out;
}

}  // namespace voxray
