#pragma once
// Analytic scenes for the lighting models (issue 15), made from signed distances so that
// trilinear reconstruction puts each surface within a few hundredths of a voxel of where
// the closed forms put it: stored value = clamp(-1000 * distance, -1000, 1000) HU (outside
// negative), 1 mm voxels, identity orientation. The transfer functions classify by HU.
#include <functional>
#include <vector>

#include "voxray/engine/render_params.h"
#include "voxray/io/image.h"
#include "voxray/io/volume.h"

namespace voxray::test {

// value = clamp(-1000 * sdf(voxel position), -1000, 1000), the sdf in voxels (= mm).
Volume sdfVolume(glm::ivec3 dims, const std::function<double(const glm::dvec3&)>& sdf);

// The opaque step at 0 HU: transparent below, opacity 1 (white) from 0 HU up.
std::vector<ControlPoint> opaqueAboveZero();
// One opacity (white) for every value.
std::vector<ControlPoint> uniformOpacity(double alpha);

// World position (LPS mm from the volume centre, the renderers' world) of voxel position pv.
glm::dvec3 worldOf(const Volume& v, const glm::dvec3& pv);

// dvr, shaded, a fixed light at `lightWorld`, orthographic, a custom table.
RenderParams litParams(Lighting lighting, const std::vector<ControlPoint>& tf,
                       glm::dvec3 lightWorld, int width = 48, int height = 36);

// A faint medium (opacity 0.05 per mm; -500 HU falling 10 HU per mm upward, so that its
// gradient, the shading normal, points down) under an opaque slab (z 30..36, 1000 HU),
// 32x32x48 voxels, with three frames: shadows with the light above the slab, the same with
// phong's ambient term only, and shadows with the light below.
struct SlabScene {
  Volume volume;
  RenderParams above, ambientOnly, below;
};
SlabScene slabScene();

// Peak signal-to-noise ratio of a against b, 0..1 channels (infinite when equal).
double psnr(const std::vector<float>& a, const std::vector<float>& b);
// The same for an 8-bit kernel image against a float reference.
double psnr(const Image& a, const std::vector<float>& reference);

}  // namespace voxray::test
