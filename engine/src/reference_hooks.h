#pragma once
// What the Monte Carlo reference (monte_carlo_reference.cpp) changes in the double-precision
// reference renderer: each pixel's own random generator, a random jitter per pixel instead
// of the kernels' hash, and the light coefficients of every shaded sample from a lighting
// estimator. Without hooks the renderer is exactly the kernels' algorithm.
#include <cstdint>
#include <functional>
#include <random>

#include "voxray/engine/reference_renderer.h"

namespace voxray {

using Rng = std::mt19937_64;

struct ReferenceHooks {
  // The light coefficients of a sample shaded at `world` (LPS mm, the frame's world).
  std::function<LightParams(const glm::dvec3& world, Rng& rng)> light;
  // Seeds each pixel's generator with (stream, px, py): one realisation of the image.
  uint64_t stream = 0;
};

struct OverlayClassifier;

// SEG: label-aware dvr (renderReferenceFloat(v, p, seg)); OVERLAY: fused dvr; null: none.
FloatImage renderReferenceFloat(const Volume& v, const RenderParams& p, ReferenceHits* hits,
                                const ReferenceHooks* hooks, const Segmentation* seg = nullptr,
                                const OverlayClassifier* overlay = nullptr);

}  // namespace voxray
