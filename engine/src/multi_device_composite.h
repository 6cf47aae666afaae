#pragma once
// The host's half of a sort-last frame (multi_device.h): the devices' partial images into one.
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/multi_device.h"  // PartImage
#include "voxray/engine/render_params.h"
#include "voxray/io/image.h"

namespace voxray {

// Composites PARTS (all WIDTH x HEIGHT) into OUT: dvr "over" front to back in each pixel's
// order, stopping once the opacity reaches EARLYTERMINATION as the one-device ray does, then
// the background behind; iso the hit of the lowest index; mip the maximum, the background
// where no part's ray met the clip box. Rounds as the kernels' to_rgba8 (to nearest even).
void compositeParts(Mode mode, const std::vector<const PartImage*>& parts, int width, int height,
                    glm::vec3 background, float earlyTermination, Image& out);

}  // namespace voxray
