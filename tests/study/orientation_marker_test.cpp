// Issue 18 item 11: the 3D view's orientation marker points where the patient's axes go on
// screen, through the engine's own camera.
#include <gtest/gtest.h>

#include "orientation_marker.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/phantom.h"

using namespace voxray;

namespace {

MarkerAxis find(const std::array<MarkerAxis, 6>& axes, char letter) {
  for (const auto& a : axes)
    if (a.letter == letter) return a;
  ADD_FAILURE() << "no axis " << letter;
  return {};
}

std::array<MarkerAxis, 6> markerFor(double azimuth, double elevation) {
  Volume v = makeHeadPhantom(16);
  RenderParams p;
  p.camera.azimuthDeg = azimuth;
  p.camera.elevationDeg = elevation;
  return orientationMarker(makeViewGeometry(v, p));
}

TEST(OrientationMarker, AnteriorViewShowsLeftOnTheRightAndHeadUp) {
  auto m = markerFor(0.0, 0.0);  // facing the patient
  EXPECT_NEAR(find(m, 'L').tip.x, 1.0, 1e-9);
  EXPECT_NEAR(find(m, 'L').tip.y, 0.0, 1e-9);
  EXPECT_NEAR(find(m, 'R').tip.x, -1.0, 1e-9);
  EXPECT_NEAR(find(m, 'S').tip.y, -1.0, 1e-9);  // up on screen
  EXPECT_NEAR(find(m, 'I').tip.y, 1.0, 1e-9);
  EXPECT_NEAR(find(m, 'A').towards, 1.0, 1e-9);  // the face looks at us
  EXPECT_NEAR(glm::length(find(m, 'A').tip), 0.0, 1e-9);
  EXPECT_EQ(m.back().letter, 'A');  // drawn last, over the others
  EXPECT_EQ(m.front().letter, 'P');
}

TEST(OrientationMarker, FollowsTheCamera) {
  auto left = markerFor(90.0, 0.0);  // from the patient's left
  EXPECT_NEAR(find(left, 'L').towards, 1.0, 1e-9);
  EXPECT_NEAR(find(left, 'A').tip.x, -1.0, 1e-9);  // the face to the viewer's left
  EXPECT_NEAR(find(left, 'S').tip.y, -1.0, 1e-9);
  auto above = markerFor(0.0, 90.0);  // from above
  EXPECT_NEAR(find(above, 'S').towards, 1.0, 1e-6);
  EXPECT_NEAR(find(above, 'L').tip.x, 1.0, 1e-6);
  // Tilted up from the anterior view, the screen's top turns to the back of the head.
  EXPECT_NEAR(find(above, 'P').tip.y, -1.0, 1e-6);
  EXPECT_NEAR(find(above, 'A').tip.y, 1.0, 1e-6);
}

}  // namespace
