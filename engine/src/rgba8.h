#pragma once
// A colour component in [0, 1] as a byte the way the kernels' to_rgba8 makes it
// (kernels/shading/shading.cl: convert_uchar_sat_rte(clamp(c, 0, 1) * 255)), for the host's
// composites: one copy that they share.
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace voxray {

inline uint8_t toRgba8Byte(float c) {
  return uint8_t(std::nearbyint(std::clamp(c, 0.0f, 1.0f) * 255.0f));  // default mode: even
}

}  // namespace voxray
