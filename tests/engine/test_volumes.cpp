#include "test_volumes.h"

#include <cmath>

namespace voxray::test {

namespace {
Volume blank(glm::ivec3 dims, glm::dvec3 spacing) {
  Volume v;
  v.dims = dims;
  v.spacingMm = spacing;
  v.voxels.assign(v.voxelCount(), 0);
  return v;
}
}  // namespace

Volume ball(glm::ivec3 dims, double radius, double inside, double outside, glm::dvec3 spacing) {
  Volume v = blank(dims, spacing);
  glm::dvec3 c = (glm::dvec3(dims) - 1.0) * 0.5;
  glm::dvec3 bump = c + glm::dvec3(radius * 0.6, -radius * 0.5, radius * 0.4);
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) {
        glm::dvec3 p(x, y, z);
        double d = glm::length(p - c) - radius;
        double db = glm::length(p - bump) - radius * 0.35;
        double s = std::min(d, db);
        double f = 0.5 - 0.5 * std::tanh(s);  // 1 inside, 0 outside
        v.voxels[v.index(x, y, z)] = int16_t(std::lround(outside + (inside - outside) * f));
      }
  return v;
}

Volume rampX(glm::ivec3 dims, double a, double b) {
  Volume v = blank(dims, glm::dvec3(1.0));
  for (int z = 0; z < dims.z; ++z)
    for (int y = 0; y < dims.y; ++y)
      for (int x = 0; x < dims.x; ++x) v.voxels[v.index(x, y, z)] = int16_t(std::lround(a + b * x));
  return v;
}

Volume constant(glm::ivec3 dims, int16_t value) {
  Volume v = blank(dims, glm::dvec3(1.0));
  v.voxels.assign(v.voxelCount(), value);
  return v;
}

}  // namespace voxray::test
