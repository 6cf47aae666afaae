#pragma once
// The 3D view's orientation marker: the patient axes L/R, A/P, S/I as the camera sees them
// (world coordinates are patient LPS), drawn small in a corner so that a turned volume
// still says which way is left.
#include <array>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "voxray/engine/camera.h"

namespace voxray {

// The marker's size on screen: its letters are laid out in pixels so that they never touch.
struct MarkerLayout {
  double armPx = 30.0;     // length of an arm seen side-on
  double letterPx = 16.0;  // a letter's box; two letters' centres stay this far apart
  double gapPx = 9.0;      // from an arm's tip to its letter's centre
};

struct MarkerAxis {
  char letter;     // 'L', 'R', 'P', 'A', 'S', 'I'
  glm::dvec2 tip;  // on screen, x right, y down, length <= 1 (shorter when seen end-on)
  double towards;  // > 0: points towards the viewer (drawn over the others)
  // The letter's centre in pixels from the marker's centre, beyond the tip, and its opacity:
  // 0 (hidden) for an arm seen nearly end-on, whose letter would sit on the centre among
  // the others, rising to 1 as the arm turns side-on; 0 too for a letter that cannot be
  // placed clear of the longer arms' letters.
  glm::dvec2 label{0.0};
  double labelAlpha = 0.0;
};

// Arms shorter than kMarkerHideLength (of a side-on arm) show no letter; from there to
// kMarkerFullLength the letter fades in.
inline constexpr double kMarkerHideLength = 0.35, kMarkerFullLength = 0.6;

// The six half-axes for the view G, farthest first (the order to draw them in).
std::array<MarkerAxis, 6> orientationMarker(const ViewGeometry& g, const MarkerLayout& layout = {});

}  // namespace voxray
