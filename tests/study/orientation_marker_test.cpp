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

// Issue 41 item 8: the letters crowded while rotating: an arm pointing nearly at the viewer
// put its letter on the centre, over the others'. Such letters hide, fade in as the arm
// turns side-on, and no two shown letters overlap, at any camera.
TEST(OrientationMarker, EndOnLettersHideAndFadeIn) {
  auto front = markerFor(0.0, 0.0);
  EXPECT_EQ(find(front, 'A').labelAlpha, 0.0);
  EXPECT_EQ(find(front, 'P').labelAlpha, 0.0);
  for (char c : {'L', 'R', 'S', 'I'}) EXPECT_EQ(find(front, c).labelAlpha, 1.0) << c;
  const MarkerLayout layout;
  EXPECT_NEAR(find(front, 'L').label.x, layout.armPx + layout.gapPx, 1e-9);
  EXPECT_NEAR(find(front, 'S').label.y, -(layout.armPx + layout.gapPx), 1e-9);

  // Turned 20 degrees: A's arm is 0.34 long; its letter sat 13 px from the centre, among
  // the arms. Hidden now. At 30 degrees (0.5) it fades in, at 45 (0.71) it is opaque.
  EXPECT_EQ(find(markerFor(20.0, 0.0), 'A').labelAlpha, 0.0);
  EXPECT_NEAR(find(markerFor(30.0, 0.0), 'A').labelAlpha, 0.6, 1e-9);
  // At 45 degrees A's arm lies on R's on screen: both letters show, one turned aside.
  const auto diagonal = markerFor(45.0, 0.0);
  const MarkerAxis a = find(diagonal, 'A'), r = find(diagonal, 'R');
  EXPECT_NEAR(glm::length(a.tip - r.tip), 0.0, 1e-9);
  EXPECT_EQ(a.labelAlpha, 1.0);
  EXPECT_EQ(r.labelAlpha, 1.0);
  EXPECT_GE(glm::length(a.label - r.label), layout.letterPx);
}

TEST(OrientationMarker, ShownLettersNeverOverlap) {
  const MarkerLayout layout;
  int turnedAside = 0, checked = 0;
  for (double azimuth = -180.0; azimuth < 180.0; azimuth += 7.0)
    for (double elevation = -85.0; elevation <= 85.0; elevation += 11.0) {
      const auto m = markerFor(azimuth, elevation);
      for (const MarkerAxis& a : m) {
        const double length = glm::length(a.tip);
        if (length < kMarkerHideLength) {
          EXPECT_EQ(a.labelAlpha, 0.0);
        }
        if (a.labelAlpha <= 0.0) continue;
        // Beyond its own arm's tip, within 40 degrees of where the arm points.
        const double cosine = glm::dot(a.label, a.tip) / (glm::length(a.label) * length);
        EXPECT_GE(cosine, std::cos(glm::radians(40.0)) - 1e-9) << a.letter;
        turnedAside += cosine < 1.0 - 1e-9;
        for (const MarkerAxis& b : m)
          if (&a != &b && b.labelAlpha > 0.0) {
            ++checked;
            EXPECT_GE(glm::length(a.label - b.label), layout.letterPx - 1e-9)
                << a.letter << b.letter << " at " << azimuth << "/" << elevation;
          }
      }
    }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(turnedAside, 0);  // the rule was needed: some letters had to move
}

}  // namespace
