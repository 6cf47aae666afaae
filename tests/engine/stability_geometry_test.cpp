// Stability at geometric extremes: axis-parallel and grazing rays, the camera inside the
// volume or the clip box, degenerate clip boxes, extreme zoom, step and image size. Each
// case asserts through expectStable (stability_helpers.h).
#include <gtest/gtest.h>

#include <cmath>

#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/camera.h"

namespace voxray {

namespace {

// Orthographic from anterior: forward is exactly (0, 1, 0), right (1, 0, 0), up (0, 0, 1),
// and with an odd image size the centre pixel's ray starts exactly at the pan point.
RenderParams axisView(Mode m, glm::dvec2 pan = glm::dvec2(0.0)) {
  RenderParams p = test::tinyParams(m, 33, 25);
  p.camera.projection = Projection::Orthographic;
  p.camera.panMm = pan;
  return p;
}

}  // namespace

TEST(StabilityGeometry, RaysExactlyParallelToAnAxis) {
  for (Mode m : test::kAllModes) {
    RenderParams p = axisView(m);
    ASSERT_EQ(makeViewGeometry(test::ball16(), p).forward, glm::dvec3(0.0, 1.0, 0.0));
    test::expectStable(test::ball16(), p, "orthographic along y");
    p.camera.projection = Projection::Perspective;  // the centre pixel looks along y exactly
    test::expectStable(test::ball16(), p, "perspective, centre ray along y");
    p.camera.elevationDeg = 90.0;  // from above: sin/cos leave ~1e-17 components
    test::expectStable(test::ball16(), p, "from above");
  }
}

TEST(StabilityGeometry, RaysGrazingFacesAndEdgesOfTheVolume) {
  // The box is [-8, 8] mm on each axis: the centre column (pan x = -8) runs exactly along
  // the face x = -0.5 voxel, the centre pixel with pan (8, 8) along an edge.
  for (Mode m : test::kAllModes)
    for (glm::dvec2 pan : {glm::dvec2(-8, 0), glm::dvec2(8, 0), glm::dvec2(0, 8), glm::dvec2(8, 8),
                           glm::dvec2(-8, -8)})
      test::expectStable(test::ball16(), axisView(m, pan),
                         "pan " + std::to_string(pan.x) + "," + std::to_string(pan.y));
}

TEST(StabilityGeometry, RaysThroughACornerAndAlongTheDiagonal) {
  // Looking down the body diagonal; the centre ray passes (to rounding) through a corner
  // on the silhouette, or enters at the near corner and leaves at the far one.
  for (Mode m : test::kAllModes)
    for (glm::dvec3 corner : {glm::dvec3(8, 8, 8), glm::dvec3(8, -8, 8)}) {
      RenderParams p = test::tinyParams(m, 33, 25);
      p.camera.azimuthDeg = 45.0;
      p.camera.elevationDeg = std::atan(1.0 / std::sqrt(2.0)) * 180.0 / 3.14159265358979323846;
      ViewGeometry g = makeViewGeometry(test::ball16(), p);
      p.camera.panMm = {glm::dot(corner, g.right), glm::dot(corner, g.up)};
      test::expectStable(test::ball16(), p, "corner " + std::to_string(corner.y));
    }
}

TEST(StabilityGeometry, RaysGrazingTheClipBox) {
  // clip x from 0.25 to 0.75 of 16 voxels: faces at voxel 3.5 and 11.5, world -4 and 4.
  for (Mode m : test::kAllModes)
    for (double x : {-4.0, 4.0}) {
      RenderParams p = axisView(m, {x, 0.0});
      p.clip.lo = {0.25, 0.0, 0.25};
      p.clip.hi = {0.75, 1.0, 0.75};
      test::expectStable(test::ball16(), p, "clip face");
      p.camera.panMm = {x, 4.0};
      test::expectStable(test::ball16(), p, "clip edge");
    }
}

TEST(StabilityGeometry, CameraInsideTheVolumeAndInsideTheClipBox) {
  for (Mode m : test::kAllModes) {
    RenderParams p = test::tinyParams(m);
    p.camera.distanceMm = 2.0;  // the eye sits inside the ball, 2 mm from the centre
    test::expectStable(test::ball16(), p, "eye inside the volume");
    p.clip.lo = glm::dvec3(0.3);
    p.clip.hi = glm::dvec3(0.7);
    test::expectStable(test::ball16(), p, "eye inside the clip box");
    p.camera.projection = Projection::Orthographic;
    test::expectStable(test::ball16(), p, "orthographic eye inside the clip box");
  }
}

TEST(StabilityGeometry, ClipBoxOfZeroThickness) {
  for (Mode m : test::kAllModes)
    for (double az : {0.0, 90.0, 30.0}) {
      RenderParams p = test::tinyParams(m);
      p.camera.azimuthDeg = az;  // 0: rays in the plane; 90: across it
      p.clip.lo = {0.5, 0.0, 0.0};
      p.clip.hi = {0.5, 1.0, 1.0};
      test::expectStable(test::ball16(), p, "zero-thickness clip, azimuth " + std::to_string(az));
    }
}

TEST(StabilityGeometry, VolumeSeenEdgeOn) {
  Volume slab = test::ball({16, 16, 1}, 5.0);
  for (Mode m : test::kAllModes) {
    RenderParams p = test::tinyParams(m);
    test::expectStable(slab, p, "16x16x1 from the side");
    p.camera.projection = Projection::Orthographic;
    test::expectStable(slab, p, "16x16x1 from the side, orthographic");
  }
}

TEST(StabilityGeometry, ZoomFromOneThousandthToOneThousand) {
  for (Mode m : test::kAllModes)
    for (Projection proj : {Projection::Perspective, Projection::Orthographic})
      for (double zoom : {1e-3, 1e-1, 1e1, 1e3}) {
        RenderParams p = test::tinyParams(m);
        p.camera.zoom = zoom;
        p.camera.projection = proj;
        test::expectStable(test::ball16(), p, "zoom " + std::to_string(zoom));
      }
}

TEST(StabilityGeometry, StepsFromOneThousandthToTenVoxels) {
  Volume v = test::ball({8, 8, 8}, 2.5);
  for (Mode m : test::kAllModes)
    for (double step : {1e-3, 1e-2, 3.0, 10.0}) {
      RenderParams p = test::tinyParams(m);
      p.stepMm = step;
      // The reference sums thousands of tiny dvr segments in double, the kernel in float:
      // allow two levels of drift at a 1e-3 step.
      test::Agreement tol;
      if (step < 0.1 && m == Mode::Dvr) tol.meanAbs = 2.0, tol.fractionOver3 = 0.25;
      test::expectStable(v, p, "step " + std::to_string(step), tol);
    }
}

TEST(StabilityGeometry, Output4096x4096) {
  Volume v = test::ball({2, 2, 2}, 0.6);
  RenderParams p = test::tinyParams(Mode::Mip, 4096, 4096);
  test::expectStable(v, p, "4096x4096 mip of 2x2x2");
}

}  // namespace voxray
