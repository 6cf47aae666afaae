#pragma once
// The 1 cm³ peak sphere's voxel weights, shared by the plane ROI's peak (roi_peak.cpp) and
// a 3D mask's (mask_peak.cpp).
#include <vector>

#include <glm/glm.hpp>

namespace voxray::peak {

// Sub-samples per axis of a cell the sphere's surface crosses: its fraction is then good to
// about 1e-3 of a cell, and the 1 cm³ sphere's summed weight to about 1e-3 relative (the
// tests measure it).
constexpr int kSubSamples = 16;

struct Weight {
  glm::ivec3 offset;
  double w;
};

// The sphere's voxel weights around a voxel centre: the fraction of each cell inside. The voxel
// axes are orthogonal (the direction is orthonormal), so an offset's length in mm is its
// index offset times the spacing, whatever the orientation: one kernel serves every centre.
inline std::vector<Weight> sphereWeights(const glm::dvec3& spacing, double r) {
  const glm::ivec3 reach = glm::ivec3(glm::ceil(r / spacing + 0.5));
  std::vector<Weight> out;
  for (int dk = -reach.z; dk <= reach.z; ++dk)
    for (int dj = -reach.y; dj <= reach.y; ++dj)
      for (int di = -reach.x; di <= reach.x; ++di) {
        const glm::dvec3 c = glm::dvec3(di, dj, dk) * spacing, h = 0.5 * spacing;
        // The cell's nearest and farthest points from the sphere's centre (an axis-aligned box).
        const glm::dvec3 near = glm::max(glm::abs(c) - h, glm::dvec3(0.0));
        const glm::dvec3 far = glm::abs(c) + h;
        if (glm::dot(near, near) >= r * r) continue;
        double w = 1.0;
        if (glm::dot(far, far) > r * r) {
          int in = 0;
          for (int z = 0; z < kSubSamples; ++z)
            for (int y = 0; y < kSubSamples; ++y)
              for (int x = 0; x < kSubSamples; ++x) {
                const glm::dvec3 p =
                    c - h + (glm::dvec3(x, y, z) + 0.5) / double(kSubSamples) * spacing;
                in += glm::dot(p, p) <= r * r;
              }
          w = double(in) / double(kSubSamples * kSubSamples * kSubSamples);
        }
        if (w > 0.0) out.push_back({{di, dj, dk}, w});
      }
  return out;
}

}  // namespace voxray::peak
