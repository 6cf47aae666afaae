#pragma once
// A point on the iso surface under a pixel of the 3D view, from the raycaster's first-hit
// output (Raycaster::renderWithHits: each pixel's refined hit in voxel coordinates).
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "no_qt.h"

namespace voxray::ui {

// The hit at PIXEL of a SIZE frame's hits, or none where the ray met no surface (dvr and
// mip frames have none) or PIXEL lies outside the frame. A hit on the entry face or a clip
// cap (the volume is cut open there) counts: it is a visible surface point too.
std::optional<glm::dvec3> surfaceHitAt(const std::vector<glm::vec4>& hits, glm::ivec2 size,
                                       glm::ivec2 pixel);

}  // namespace voxray::ui
