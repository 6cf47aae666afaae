#include "orientation_marker.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace voxray {

namespace {

// P turned by DEG degrees about the marker's centre.
glm::dvec2 turned(glm::dvec2 p, double deg) {
  const double a = glm::radians(deg), c = std::cos(a), s = std::sin(a);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

// Letters fade with foreshortening and keep LAYOUT.letterPx apart: the longest arms are
// placed first, where they point; a shorter arm's letter turns up to 30 degrees about the
// centre to clear them, or hides.
void placeLetters(std::array<MarkerAxis, 6>& axes, const MarkerLayout& layout) {
  std::array<MarkerAxis*, 6> byLength{};
  for (size_t i = 0; i < axes.size(); ++i) byLength[i] = &axes[i];
  std::stable_sort(byLength.begin(), byLength.end(), [](const MarkerAxis* a, const MarkerAxis* b) {
    return glm::length(a->tip) > glm::length(b->tip);
  });
  std::vector<glm::dvec2> placed;
  const auto clear = [&](glm::dvec2 p) {
    return std::all_of(placed.begin(), placed.end(),
                       [&](glm::dvec2 q) { return glm::length(p - q) >= layout.letterPx; });
  };
  for (MarkerAxis* a : byLength) {
    const double length = glm::length(a->tip);
    const double fade = std::clamp(
        (length - kMarkerHideLength) / (kMarkerFullLength - kMarkerHideLength), 0.0, 1.0);
    a->labelAlpha = 0.0;
    if (fade <= 0.0) continue;
    const glm::dvec2 where = a->tip / length * (length * layout.armPx + layout.gapPx);
    for (double deg : {0.0, 10.0, -10.0, 20.0, -20.0, 30.0, -30.0, 40.0, -40.0}) {
      const glm::dvec2 p = turned(where, deg);
      if (!clear(p)) continue;
      a->label = p;
      a->labelAlpha = fade;
      placed.push_back(p);
      break;
    }
  }
}

}  // namespace

std::array<MarkerAxis, 6> orientationMarker(const ViewGeometry& g, const MarkerLayout& layout) {
  // LPS: +x is the patient's left, +y posterior, +z superior.
  static constexpr char kLetters[3][2] = {{'L', 'R'}, {'P', 'A'}, {'S', 'I'}};
  std::array<MarkerAxis, 6> axes{};
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      glm::dvec3 d(0.0);
      d[axis] = side == 0 ? 1.0 : -1.0;
      // A direction, not a point: the marker ignores perspective, as a compass would.
      axes[size_t(axis * 2 + side)] = {kLetters[axis][side],
                                       {glm::dot(d, g.right), -glm::dot(d, g.up)},
                                       -glm::dot(d, g.forward)};
    }
  }
  placeLetters(axes, layout);
  std::sort(axes.begin(), axes.end(),
            [](const MarkerAxis& a, const MarkerAxis& b) { return a.towards < b.towards; });
  return axes;
}

}  // namespace voxray
