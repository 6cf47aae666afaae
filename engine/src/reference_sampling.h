#pragma once
// Double-precision reconstruction and gradients, mirroring kernels/sampling.cl and
// kernels/gradients.cl (the same clamping, rounding and operator weights).
#include <glm/glm.hpp>

#include "voxray/engine/render_params.h"

namespace voxray {

struct Volume;

double sampleVolume(const Volume& v, Interp interp, const glm::dvec3& p);
// Gradient in stored units per voxel along the volume axes; exactly 0 when it is at most
// 1e-5 times the largest |voxel| the stencil read (cancellation noise in the kernel's float).
glm::dvec3 volumeGradient(const Volume& v, Interp interp, Gradient op, const glm::dvec3& p);
// Volume reads one volumeGradient() call makes (6 or 26).
int gradientSamples(Gradient op);

// The kernel's per-pixel jitter fraction in [0, 1), bit-exact (kernels/jitter_hash.h).
float jitterFraction(int px, int py);

}  // namespace voxray
