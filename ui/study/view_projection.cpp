#include "view_projection.h"

namespace voxray {

std::optional<glm::dvec2> ViewProjection::project(const glm::dvec3& world) const {
  glm::dvec3 rel = world - g.eye;
  double z = glm::dot(rel, g.forward);
  double sx = glm::dot(rel, g.right), sy = glm::dot(rel, g.up);
  if (!g.orthographic) {
    if (z <= 1e-6) return std::nullopt;
    sx /= z;
    sy /= z;
  }
  double nx = sx / (g.halfHeight * g.aspect), ny = sy / g.halfHeight;
  return glm::dvec2((nx + 1.0) * 0.5 * size.x, (1.0 - ny) * 0.5 * size.y);
}

double ViewProjection::mmPerPixel() const {
  double halfHeightMm = g.halfHeight;
  if (!g.orthographic) halfHeightMm *= glm::length(g.eye);  // the centre is the world origin
  return 2.0 * halfHeightMm / size.y;
}

ViewProjection makeViewProjection(const Volume& v, const RenderParams& p, glm::dvec2 viewSize) {
  RenderParams sized = p;
  // The aspect is the view's; the render resolution only changes sharpness.
  sized.width = int(viewSize.x);
  sized.height = int(viewSize.y);
  return {makeViewGeometry(v, sized), viewSize};
}

}  // namespace voxray
