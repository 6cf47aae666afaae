#pragma once
// The segment editor's scissors in the 3D view: a polygon drawn on the screen removes from a
// segment every voxel whose centre the view's camera projects inside it, through the whole
// depth (everything behind the polygon), as one undo step.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "segmentation_model.h"
#include "view_projection.h"

namespace voxray {

// Even-odd rule; a polygon of fewer than three points holds nothing.
bool insidePolygon(const std::vector<glm::dvec2>& polygon, glm::dvec2 p);

// LABEL's voxels that stay: those whose centres PROJ (the view's projection, image pixels)
// puts outside POLYGON or behind the eye.
Mask scissorsKeep(const Segmentation& s, const Volume& v, const ViewProjection& proj,
                  const std::vector<glm::dvec2>& polygon, uint8_t label);

// Cuts LABEL with the polygon: one undo step ("Scissors"); nothing when nothing lies inside.
// Throws an input Error when the label names no segment.
void applyScissors(SegmentationModel& m, const Volume& v, const ViewProjection& proj,
                   const std::vector<glm::dvec2>& polygon, uint8_t label);

}  // namespace voxray
