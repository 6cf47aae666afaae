// Shading at the extremes of the inputs: never NaN, values where the maths says.
#include <gtest/gtest.h>

#include "stability_helpers.h"
#include "test_volumes.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/engine/reference_renderer.h"

namespace voxray {

namespace {}  // namespace

TEST(Shading, ZeroGradientIsLitAsFacingTheViewerNotNaN) {
  // A constant volume: every gradient is exactly zero, so the normal falls back to the
  // view vector. CT-Bone at 500 HU has green 0.698 and opacity 0.565 per mm; with the
  // light at the eye the centre ray is lit head-on: 0.698 * (0.15 + 0.75) + 0.25 = 0.878,
  // times the accumulated opacity, which stops between 0.99 and 1 (early termination).
  Volume v = test::constant({16, 16, 16}, 500);
  RenderParams p;
  p.width = 16;
  p.height = 16;
  p.mode = Mode::Dvr;
  p.preset = "CT-Bone";
  p.light.position = {0.0, 0.0, 0.0};  // at the eye
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  for (const Image& img : {rc.render(p), renderReference(v, p)}) {
    int g = img.pixel(8, 8)[1];
    EXPECT_GE(g, 220);
    EXPECT_LE(g, 225);
  }
}

TEST(Shading, CutFaceIsShadedAsAFlatCapFacingTheViewer) {
  Volume v = test::constant({8, 8, 8}, 500);
  RenderParams p;
  p.width = 16;
  p.height = 16;
  p.mode = Mode::Iso;
  p.isoLo = 100.0;
  p.surfaceColor = {0.4, 0.4, 0.4};
  p.light.position = {0.0, 0.0, 0.0};  // at the eye
  p.camera.zoom = 4.0;                 // every pixel sees the volume
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  Image img = rc.render(p);
  // The first sample is on the entry face: the cap normal faces the viewer exactly and
  // the light is at the eye: colour * (ambient + diffuse) + specular = 0.4 * 0.9 + 0.25 = 0.61 ->
  // 156 (centre pixel).
  EXPECT_NEAR(img.pixel(8, 8)[0], 156, 1);
  Image ref = renderReference(v, p);
  EXPECT_NEAR(ref.pixel(8, 8)[0], 156, 1);
}

TEST(Shading, LightOnTheLeftLightsTheLeftSide) {
  Volume v = test::ball({32, 32, 32}, 10.0);
  RenderParams p;
  p.width = 64;
  p.height = 64;
  p.mode = Mode::Iso;
  p.isoLo = 0.0;
  p.light.followCamera = false;
  p.light.position = {1000.0, -300.0, 0.0};  // patient's left (+x), in front
  p.camera.zoom = 2.0;
  Raycaster rc(test::pocl(), v, VolumeStorage::Buffer);
  Image img = rc.render(p);
  // Anterior view: patient's left is on the image's right.
  int right = img.pixel(44, 32)[0], left = img.pixel(20, 32)[0];
  EXPECT_GT(right, left + 40) << "right " << right << " left " << left;
}

}  // namespace voxray
