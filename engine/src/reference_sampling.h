#pragma once
// Double-precision reconstruction and gradients, mirroring kernels/reconstruction/sampling.cl and
// kernels/reconstruction/gradients.cl (the same clamping, rounding and operator weights).
#include <glm/glm.hpp>

#include "voxray/engine/camera.h"
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

// Pixel (px, py)'s ray in world (ow, dw; dw unit) and voxel coordinates (ov, dv per mm),
// clipped to the clip box [t0, t1] in mm, as kernels/intersection/ray.cl's pixel_ray. False on a
// miss.
struct PixelRay {
  glm::dvec3 ow, dw, ov, dv;
  double t0 = 0.0, t1 = 0.0;
  int axis = -1;  // the clip box's entry axis, -1 when the eye is inside it
};
bool pixelRay(const ViewGeometry& g, int px, int py, int width, int height, PixelRay& r);

// v / |v|, or fallback when v is zero, tiny or not finite (kernels/math.cl's safe_normalize).
glm::dvec3 safeNormalize(glm::dvec3 v, const glm::dvec3& fallback);

}  // namespace voxray
