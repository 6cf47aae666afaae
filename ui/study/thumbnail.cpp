#include "thumbnail.h"

#include <algorithm>

#include "voxray/io/volume.h"

namespace voxray {

WindowLevel defaultThumbnailWindow(const Volume& v, const std::string& modality, bool isVolume) {
  if ((modality == "CT" && isVolume) || v.voxelCount() == 0) return {400.0, 40.0};
  int k = v.dims.z / 2;
  auto first = v.voxels.begin() + std::ptrdiff_t(v.index(0, 0, k));
  auto [lo, hi] = std::minmax_element(first, first + std::ptrdiff_t(v.dims.x) * v.dims.y);
  double a = v.toPhysical(*lo), b = v.toPhysical(*hi);
  return {std::max(b - a, 1.0), (a + b) / 2.0};
}

Image middleSliceThumbnail(const Volume& v, const WindowLevel& wl, int size) {
  if (v.voxelCount() == 0 || size <= 0) return {};
  Image img(size, size);
  for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;  // opaque black
  // Physical width and height of the slice decide the drawn rectangle.
  double w = v.dims.x * v.spacingMm.x, h = v.dims.y * v.spacingMm.y;
  double scale = size / std::max(w, h);
  int dw = std::max(1, int(w * scale)), dh = std::max(1, int(h * scale));
  int x0 = (size - dw) / 2, y0 = (size - dh) / 2;
  int k = v.dims.z / 2;
  for (int y = 0; y < dh; ++y) {
    int j = std::min(v.dims.y - 1, int((y + 0.5) * v.dims.y / dh));
    for (int x = 0; x < dw; ++x) {
      int i = std::min(v.dims.x - 1, int((x + 0.5) * v.dims.x / dw));
      uint8_t g = mapToGrey(v.toPhysical(v.at(i, j, k)), wl);
      uint8_t* p = img.pixel(x0 + x, y0 + y);
      p[0] = p[1] = p[2] = g;
    }
  }
  return img;
}

}  // namespace voxray
