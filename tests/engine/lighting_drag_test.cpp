// Shadows during a drag with the light following the camera (issue 40 item 4): a held light
// grid (Raycaster::holdLightGrid) is not rebuilt while only the light moves, the frame after
// the release is byte for byte the frame of a raycaster that never held, and a held frame's
// error against its converged frame is bounded.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "accuracy_cthead.h"
#include "lighting_scenes.h"
#include "stability_helpers.h"
#include "voxray/engine/raycaster.h"

namespace voxray {

namespace {

// A ball resting above a plane: the plane holds its shadow, which moves over it as the light
// turns with the camera.
const Volume& ballOnPlane() {
  static Volume v = test::sdfVolume({48, 48, 40}, [](const glm::dvec3& q) {
    return std::min(q.z - 8.0, glm::length(q - glm::dvec3(23.5, 23.5, 20.0)) - 7.0);
  });
  return v;
}

// The view from above the front, the light following the camera (the default) up and to the
// right of the eye, so that the ball's shadow falls on the plane beside it.
RenderParams ballScene() {
  RenderParams p = test::litParams(Lighting::Shadows, test::opaqueAboveZero(), glm::dvec3(0.0));
  p.light.followCamera = true;
  p.light.position = glm::dvec3(0.8, 0.9, 0.0);
  p.camera.elevationDeg = 35.0;
  p.camera.azimuthDeg = 20.0;
  return p;
}

RenderParams turned(RenderParams p, double degrees) {
  p.camera.azimuthDeg += degrees;
  return p;
}

// PSNR of the 8-bit colour channels, peak 255.
double imagePsnr(const Image& a, const Image& b) {
  double sq = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = (double(a.rgba[i]) - double(b.rgba[i])) / 255.0;
    sq += d * d;
    ++n;
  }
  return sq > 0.0 ? 10.0 * std::log10(double(n) / sq) : 99.0;
}

struct HeldError {
  double held = 0, phong = 0;  // PSNR (dB) against the converged frame
};

// The frame DEGREES into a drag from STILL, lit through the grid of the drag's start,
// against the same frame with its own grid (the release's), and phong's against it.
HeldError heldError(const Volume& v, const RenderParams& still, double degrees) {
  Raycaster rc(test::pocl(), v);
  rc.render(still);
  rc.holdLightGrid(true);
  const RenderParams p = turned(still, degrees);
  Image held = rc.render(p);
  rc.holdLightGrid(false);
  Image converged = rc.render(p);
  RenderParams phong = p;
  phong.lighting = Lighting::Phong;
  Image unshadowed = rc.render(phong);
  HeldError e{imagePsnr(held, converged), imagePsnr(unshadowed, converged)};
  std::printf("held grid %.0f degrees: %.1f dB (phong %.1f dB)\n", degrees, e.held, e.phong);
  return e;
}

}  // namespace

TEST(LightingDrag, AHeldGridIsNotRebuiltAndTheReleasedFrameIsTheStillFrame) {
  Raycaster rc(test::pocl(), ballOnPlane());
  const RenderParams still = ballScene();
  rc.render(still);
  ASSERT_EQ(rc.lightingBuilds(), 1);
  rc.holdLightGrid(true);
  for (int i = 1; i <= 10; ++i) {
    // A drag frame as the drag preset plans it: half the size, twice the step.
    RenderParams drag = turned(still, 2.0 * i);
    drag.width /= 2;
    drag.height /= 2;
    drag.stepMm = 1.0;
    FrameStats st;
    rc.render(drag, &st);
    EXPECT_EQ(st.lightingMs, 0.0);
  }
  EXPECT_EQ(rc.lightingBuilds(), 1);       // 10 frames, the light 2 degrees further each
  EXPECT_EQ(rc.lightingHeldFrames(), 10);  // each lit through the start's grid
  const Image lastHeld = rc.render(turned(still, 20.0));
  rc.holdLightGrid(false);
  FrameStats st;
  Image released = rc.render(turned(still, 20.0), &st);
  EXPECT_GT(st.lightingMs, 0.0);
  EXPECT_EQ(rc.lightingBuilds(), 2);  // the release: the grid of its light
  Raycaster fresh(test::pocl(), ballOnPlane());
  EXPECT_EQ(test::maxDiff(released, fresh.render(turned(still, 20.0))), 0);
  EXPECT_GT(test::maxDiff(lastHeld, released), 0);  // the held frame was not it
  // What the grid depends on besides the light still rebuilds it while held.
  rc.holdLightGrid(true);
  RenderParams table = turned(still, 24.0);
  table.transferFunction[2].rgba.a = 0.5;
  rc.render(table);
  EXPECT_EQ(rc.lightingBuilds(), 3);
  table.clip.hi.x = 0.7;
  rc.render(table);
  EXPECT_EQ(rc.lightingBuilds(), 4);
  EXPECT_EQ(rc.lightingHeldFrames(), 11);  // the drag's 10 and lastHeld
  // Dragging the light itself (its place relative to the camera) rebuilds: its shadows are
  // what that drag is for.
  RenderParams light = table;
  light.light.position.x -= 0.2;
  rc.render(light);
  EXPECT_EQ(rc.lightingBuilds(), 5);
  EXPECT_EQ(rc.lightingHeldFrames(), 11);
}

TEST(LightingDrag, AHeldGridIsRebuiltOnceItsLightTurnedPast45Degrees) {
  // Past ~45 degrees a held grid's shadows are further from the converged frame than none
  // (light_volume.cpp, kHeldLightDeg): the drag then rebuilds it for the light it has.
  Raycaster rc(test::pocl(), ballOnPlane());
  const RenderParams still = ballScene();
  rc.render(still);
  rc.holdLightGrid(true);
  rc.render(turned(still, 20.0));  // the light less than 20 degrees from the grid's: held
  EXPECT_EQ(rc.lightingBuilds(), 1);
  rc.render(turned(still, 120.0));  // a third of a turn: the light over 45 degrees away
  EXPECT_EQ(rc.lightingBuilds(), 2);
  EXPECT_EQ(rc.lightingHeldFrames(), 1);
  rc.render(turned(still, 130.0));  // held again, on the new grid
  EXPECT_EQ(rc.lightingBuilds(), 2);
  EXPECT_EQ(rc.lightingHeldFrames(), 2);
  // The rebuilt grid is the one a still frame there builds: the held frame 10 degrees on
  // equals a fresh raycaster's held frame from the same start.
  const Image held = rc.render(turned(still, 130.0));
  Raycaster fresh(test::pocl(), ballOnPlane());
  fresh.render(turned(still, 120.0));
  fresh.holdLightGrid(true);
  EXPECT_EQ(test::maxDiff(held, fresh.render(turned(still, 130.0))), 0);
}

TEST(LightingDrag, AHeldGridsErrorIsBoundedAndBelowDroppingTheShadows) {
  // The ball's shadow on the plane, the grid held 10 and 30 degrees of the light's turn
  // (5 and 15 drag frames of the 3D view's 2 degrees). Measured on PoCL (AVX-512): 33.1 and
  // 27.1 dB, phong (the shadow dropped) 18.9 and 19.5 dB. Each bound sits 1 dB below the
  // figure: the images are 8-bit, and another device's float rounding moves a few pixels
  // of the shadow's edge by a level, far less than 1 dB here.
  HeldError ten = heldError(ballOnPlane(), ballScene(), 10.0);
  HeldError thirty = heldError(ballOnPlane(), ballScene(), 30.0);
  EXPECT_GE(ten.held, 32.0);
  EXPECT_GE(thirty.held, 26.0);
  EXPECT_GT(ten.held, ten.phong + 10.0);  // holding the shadows beats dropping them
  EXPECT_GT(thirty.held, thirty.phong + 5.0);
}

TEST(LightingDrag, AHeldGridsErrorOnCtheadIsBounded) {
  const Volume* v = test::cthead();
  if (!v) GTEST_SKIP() << "CThead is not in the shared data beside the checkout";
  RenderParams p = test::ctheadDvr();
  p.lighting = Lighting::Shadows;
  // CT-Bone dvr, 128x96: measured 45.4 and 39.2 dB (phong 32.1 and 32.2 dB) on PoCL; the
  // bounds 1 dB below, as above.
  HeldError ten = heldError(*v, p, 10.0);
  HeldError thirty = heldError(*v, p, 30.0);
  EXPECT_GE(ten.held, 44.0);
  EXPECT_GE(thirty.held, 38.0);
  EXPECT_GT(ten.held, ten.phong + 10.0);
  EXPECT_GT(thirty.held, thirty.phong + 5.0);
}

}  // namespace voxray
