#pragma once
// The 3D view's orientation marker: the patient axes L/R, A/P, S/I as the camera sees them
// (world coordinates are patient LPS), drawn small in a corner so that a turned volume
// still says which way is left.
#include <array>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "voxray/engine/camera.h"

namespace voxray {

struct MarkerAxis {
  char letter;     // 'L', 'R', 'P', 'A', 'S', 'I'
  glm::dvec2 tip;  // on screen, x right, y down, length <= 1 (shorter when seen end-on)
  double towards;  // > 0: points towards the viewer (drawn over the others)
};

// The six half-axes for the view G, farthest first (the order to draw them in).
std::array<MarkerAxis, 6> orientationMarker(const ViewGeometry& g);

}  // namespace voxray
