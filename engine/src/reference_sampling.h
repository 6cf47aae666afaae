#pragma once
// Double-precision reconstruction and gradients, mirroring kernels/sampling.cl and
// kernels/gradients.cl (the same clamping, rounding and operator weights).
#include <glm/glm.hpp>

#include "voxray/engine/render_params.h"

namespace voxray {

struct Volume;

double sampleVolume(const Volume& v, Interp interp, const glm::dvec3& p);
// Gradient in stored units per voxel along the volume axes.
glm::dvec3 volumeGradient(const Volume& v, Interp interp, Gradient op, const glm::dvec3& p);

}  // namespace voxray
