#include "slice_image.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "voxray/io/volume.h"

namespace voxray::ui {

Image renderSlice(const Volume& v, const SliceAxes& a, int slice, const WindowLevel& wl) {
  if (v.voxelCount() == 0) return {};
  int w = v.dims[a.uAxis], h = v.dims[a.vAxis];
  Image img(w, h);
  // A table over all stored values turns the per-pixel work into one lookup.
  std::array<uint8_t, 65536> lut;
  for (int s = 0; s < 65536; ++s) lut[size_t(s)] = mapToGrey(v.toPhysical(s - 32768), wl);
  glm::ivec3 voxel(0);
  voxel[a.nAxis] = std::clamp(slice, 0, v.dims[a.nAxis] - 1);
  for (int y = 0; y < h; ++y) {
    voxel[a.vAxis] = a.vFlip ? h - 1 - y : y;
    for (int x = 0; x < w; ++x) {
      voxel[a.uAxis] = a.uFlip ? w - 1 - x : x;
      uint8_t g = lut[size_t(int(v.at(voxel.x, voxel.y, voxel.z)) + 32768)];
      uint8_t* p = img.pixel(x, y);
      p[0] = p[1] = p[2] = g;
      p[3] = 255;
    }
  }
  return img;
}

double sampleValue(const Volume& v, const glm::dvec3& voxel) {
  glm::ivec3 i(glm::round(voxel));
  if (glm::any(glm::lessThan(i, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(i, v.dims)))
    return std::numeric_limits<double>::quiet_NaN();
  return v.toPhysical(v.at(i.x, i.y, i.z));
}

}  // namespace voxray::ui
