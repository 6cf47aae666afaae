#include "orientation_marker.h"

#include <algorithm>

namespace voxray {

std::array<MarkerAxis, 6> orientationMarker(const ViewGeometry& g) {
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
  std::sort(axes.begin(), axes.end(),
            [](const MarkerAxis& a, const MarkerAxis& b) { return a.towards < b.towards; });
  return axes;
}

}  // namespace voxray
