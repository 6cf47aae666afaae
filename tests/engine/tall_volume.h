#pragma once
// The out-of-core tests' volume (out_of_core_test.cpp, out_of_core_pinned_test.cpp): long in z,
// so that a small budget splits it into several parts each holding some of every structure.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "voxray/io/volume.h"

namespace voxray::test {

// 40x36x96, anisotropic: an ellipsoid of 1000 HU along z (it crosses every part), a denser rod
// off its axis and a bump, blended over about a voxel so gradients are defined.
inline const Volume& tallVolume() {
  static Volume v = [] {
    Volume t;
    t.dims = {40, 36, 96};
    t.spacingMm = {1.0, 1.1, 0.9};
    t.voxels.resize(t.voxelCount());
    for (int z = 0; z < t.dims.z; ++z)
      for (int y = 0; y < t.dims.y; ++y)
        for (int x = 0; x < t.dims.x; ++x) {
          const double ex = (x - 19.5) / 15.0, ey = (y - 17.5) / 13.0, ez = (z - 47.5) / 44.0;
          const double r = std::sqrt(ex * ex + ey * ey + ez * ez);
          double hu = -1000.0 + 2000.0 / (1.0 + std::exp((r - 1.0) * 14.0));
          const double rod = std::hypot(x - 26.0, y - 15.0);
          hu += 800.0 / (1.0 + std::exp((rod - 3.0) * 2.0)) * (z > 20 && z < 80);
          const double bump =
              std::sqrt(std::pow(x - 8.0, 2) + std::pow(y - 9.0, 2) + std::pow(z - 30.0, 2));
          hu += 1500.0 / (1.0 + std::exp((bump - 4.0) * 2.0));
          t.voxels[t.index(x, y, z)] = int16_t(std::lround(std::clamp(hu, -1024.0, 3000.0)));
        }
    return t;
  }();
  return v;
}

}  // namespace voxray::test
