#pragma once
// Small synthetic volumes for engine tests, with known geometry.
#include "voxray/io/volume.h"

namespace voxray::test {

// A ball of `inside` HU (radius r voxels, centred) in `outside` HU, smoothly blended over
// about one voxel so gradients are well defined, plus a small off-centre bump so the
// image is not symmetric.
Volume ball(glm::ivec3 dims, double radius, double inside = 1000.0, double outside = -1000.0,
            glm::dvec3 spacing = glm::dvec3(1.0));
// The stability cases' small ball: 16^3 voxels of 1 mm, radius 5.
inline const Volume& ball16() {
  static Volume v = ball({16, 16, 16}, 5.0);
  return v;
}
// value = a + b * x (x in voxels): trilinear reconstruction of it is exact.
Volume rampX(glm::ivec3 dims, double a, double b);
Volume constant(glm::ivec3 dims, int16_t value);

}  // namespace voxray::test
