#include "surface_pick.h"

namespace voxray::ui {

std::optional<glm::dvec3> surfaceHitAt(const std::vector<glm::vec4>& hits, glm::ivec2 size,
                                       glm::ivec2 pixel) {
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= size.x || pixel.y >= size.y) return std::nullopt;
  const size_t i = size_t(pixel.y) * size_t(size.x) + size_t(pixel.x);
  if (i >= hits.size() || hits[i].w < 0.0F) return std::nullopt;
  return glm::dvec3(hits[i]);
}

}  // namespace voxray::ui
