#include "slab_bounds.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "voxray/engine/camera.h"
#include "voxray/io/volume.h"

namespace voxray::mpi {

std::optional<NdcBox> slabBoundsNdc(const Volume& volume, const RenderParams& p,
                                    const PartRange& range) {
  const ViewGeometry g = makeViewGeometry(volume, p);
  const glm::dvec3 n(volume.dims);
  // The part's samples lie between the planes z = first and z = end (raycast_part.cl); a
  // slice more on either side covers what its stencils and the first/last part's open ends
  // reach, and the volume's box [-0.5, n - 0.5] ends the first and last part.
  const glm::dvec3 lo(-0.5, -0.5, std::max(-0.5, double(range.first) - 1.0));
  const glm::dvec3 hi(n.x - 0.5, n.y - 0.5, std::min(n.z - 0.5, double(range.end) + 1.0));
  const glm::dmat3 voxelToWorld = glm::inverse(g.worldToVoxel);
  // Nearer than this (mm along the view) a corner's projection is too large to be of use.
  const double nearest = 1e-3;
  NdcBox box{HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 voxel((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
    const glm::dvec3 d = voxelToWorld * (voxel - g.voxelCentre) - g.eye;
    double sx = glm::dot(d, g.right), sy = glm::dot(d, g.up);
    if (!g.orthographic) {
      const double depth = glm::dot(d, g.forward);
      if (depth < nearest) return std::nullopt;
      sx /= depth;
      sy /= depth;
    }
    const double x = sx / (g.halfHeight * g.aspect), y = sy / g.halfHeight;
    box = {std::min(box.x0, x), std::max(box.x1, x), std::min(box.y0, y), std::max(box.y1, y)};
  }
  return box;
}

}  // namespace voxray::mpi
