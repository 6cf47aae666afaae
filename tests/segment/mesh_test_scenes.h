#pragma once
// Segmentations made in code for the mesh tests.
#include <cmath>

#include "voxray/io/segmentation.h"

namespace voxray {

// A ball of RADIUS mm (label 1, "Ball", orange) on isotropic SPACING mm voxels, centred in the
// grid with 4 voxels' margin, origin and direction not trivial: LPS origin (-30, 20, 100),
// the j axis running posterior->anterior (direction column 2 = -y), so left-handed.
inline Segmentation sphereSegmentation(double radius, double spacing) {
  Segmentation s;
  const int n = int(std::ceil(2 * radius / spacing)) + 8;
  s.grid.dims = {n, n, n};
  s.grid.spacingMm = glm::dvec3(spacing);
  s.grid.originMm = {-30.0, 20.0, 100.0};
  s.grid.direction = glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1));
  s.labels.assign(s.grid.voxelCount(), 0);
  const double c = (n - 1) / 2.0;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const glm::dvec3 d = (glm::dvec3(x, y, z) - c) * spacing;
        if (glm::dot(d, d) <= radius * radius) s.labels[s.grid.index(x, y, z)] = 1;
      }
  Segment ball;
  ball.label = 1;
  ball.name = "Ball";
  ball.colour = {1.0f, 0.5f, 0.0f};
  s.segments.push_back(ball);
  return s;
}

inline glm::dvec3 sphereCentre(const Segmentation& s) {
  return s.grid.toPatient(glm::dvec3(s.grid.dims - 1) / 2.0);
}

}  // namespace voxray
