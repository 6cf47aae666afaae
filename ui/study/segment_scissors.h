#pragma once
// The segment editor's scissors in the 3D view: a polygon drawn on the screen removes from a
// segment every voxel whose centre the view's camera projects inside it, through the whole
// depth (everything behind the polygon), or keeps only those (Keep: cut away the CT table and
// headrest around the head in one lasso), as one undo step.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "segmentation_model.h"
#include "view_projection.h"

namespace voxray {

// Even-odd rule; a polygon of fewer than three points holds nothing.
bool insidePolygon(const std::vector<glm::dvec2>& polygon, glm::dvec2 p);

// Remove: what projects inside the polygon goes; Keep: only what projects inside it stays.
enum class ScissorsMode { Remove, Keep };

// LABEL's voxels that stay: Remove keeps those whose centres PROJ (the view's projection,
// image pixels) puts outside POLYGON or behind the eye; Keep those it puts inside (in front of
// the eye).
Mask scissorsKeep(const Segmentation& s, const Volume& v, const ViewProjection& proj,
                  const std::vector<glm::dvec2>& polygon, uint8_t label,
                  ScissorsMode mode = ScissorsMode::Remove);

// Cuts LABEL with the polygon: one undo step ("Scissors" or "Scissors keep"); nothing when
// nothing changes. Throws an input Error when the label names no segment.
void applyScissors(SegmentationModel& m, const Volume& v, const ViewProjection& proj,
                   const std::vector<glm::dvec2>& polygon, uint8_t label,
                   ScissorsMode mode = ScissorsMode::Remove);

}  // namespace voxray
