#pragma once
// A point on the iso surface, or dvr's first opaque point (where a ray's accumulated
// opacity reaches 0.5), under a pixel of the 3D view, from the raycaster's hit output
// (Raycaster::renderWithHits: each pixel's hit in voxel coordinates).
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "voxray/engine/render_params.h"

namespace voxray {

// The hit at PIXEL of a SIZE frame's hits, or none where the ray met no surface or never
// reached 0.5 opacity (mip frames have none) or PIXEL lies outside the frame. A hit on the
// entry face or a clip cap (the volume is cut open there) counts: it is a visible surface
// point too.
std::optional<glm::dvec3> surfaceHitAt(const std::vector<glm::vec4>& hits, glm::ivec2 size,
                                       glm::ivec2 pixel);

// The frame a pick renders, from the view's frame P: dvr marches at most half the smallest
// voxel spacing (MINSPACINGMM) per step, where its crossing of 0.5 opacity, interpolated
// within a step, lies within 0.05 voxel of the analytic point (tests/engine/dvr_pick_test.cpp);
// the quality presets' longer steps would move it by up to a step. iso keeps P: its hit is
// refined by bisection whatever the step.
RenderParams pickFrameParams(RenderParams p, double minSpacingMm);

// Why a pick in a frame rendered with P found nothing (for the status bar).
std::string pickMissMessage(const RenderParams& p);

}  // namespace voxray
