#include <gtest/gtest.h>

#include "clip_box_math.h"
#include "slice_clip.h"
#include "voxray/io/phantom.h"

using namespace voxray;

TEST(ClipBox, FacesClampAndNeverInvert) {
  ClipBox box;
  setClipFace(box, 1, 0.6);  // x high
  EXPECT_DOUBLE_EQ(box.hi.x, 0.6);
  setClipFace(box, 0, 0.9);  // x low past the high side: stops kMinClipGap before it
  EXPECT_DOUBLE_EQ(box.lo.x, 0.6 - kMinClipGap);
  setClipFace(box, 5, -3.0);  // z high below zero: at least the gap above z low
  EXPECT_DOUBLE_EQ(box.hi.z, kMinClipGap);
  setClipFace(box, 2, -1.0);
  EXPECT_DOUBLE_EQ(box.lo.y, 0.0);
  EXPECT_FALSE(box.isFull());
}

TEST(ClipBox, FaceCentresSitOnTheVolumeBox) {
  Volume v = makeHeadPhantom(32);  // 256 mm box centred on the world origin
  ClipBox box;
  EXPECT_NEAR(clipFaceCentreWorld(v, box, 1).x, 128.0, 1e-9);   // +x face: patient left
  EXPECT_NEAR(clipFaceCentreWorld(v, box, 4).z, -128.0, 1e-9);  // -z face: inferior
  setClipFace(box, 1, 0.75);
  EXPECT_NEAR(clipFaceCentreWorld(v, box, 1).x, 64.0, 1e-9);
}

TEST(ClipBox, DraggingAFaceInTheAnteriorViewFollowsTheMouse) {
  Volume v = makeHeadPhantom(32);
  RenderParams p;  // anterior view: patient left (+x) on the screen's right
  ViewProjection view = makeViewProjection(v, p, {400, 300});
  ClipBox box;
  auto handle = view.project(clipFaceCentreWorld(v, box, 1));
  ASSERT_TRUE(handle.has_value());
  EXPECT_GT(handle->x, 200.0);
  ASSERT_EQ(pickClipFace(v, box, view, *handle + glm::dvec2(3, 2)), 1);
  // Dragging the +x face towards the centre by a quarter of its distance.
  double toCentre = handle->x - 200.0;
  ClipBox moved = dragClipFace(v, box, view, 1, {-0.25 * toCentre, 40.0});  // y is ignored
  EXPECT_NEAR(moved.hi.x, 0.875, 0.02);  // perspective: approximately a quarter of a half
  EXPECT_EQ(moved.lo, box.lo);
  EXPECT_EQ(moved.hi.y, 1.0);
  // The y faces (anterior/posterior) are seen end-on from the front: not pickable.
  auto front = view.project(clipFaceCentreWorld(v, box, 2));
  ASSERT_TRUE(front.has_value());
  EXPECT_NE(pickClipFace(v, box, view, *front), std::optional<int>(2));
}

TEST(ClipBox, SliceEdgesMatchTheBoxAndDragBack) {
  glm::ivec3 dims(100, 80, 60);
  ClipBox box;
  box.lo = {0.1, 0.2, 0.3};
  box.hi = {0.9, 0.8, 0.7};
  auto coronal = sliceAxes(glm::dmat3(1.0), Orientation::Coronal);  // u = x, v = -z
  auto edges = sliceClipEdges(coronal, dims, box);
  EXPECT_EQ(edges[0].face, 0);
  EXPECT_NEAR(edges[0].position, 10.0, 1e-9);
  EXPECT_NEAR(edges[1].position, 90.0, 1e-9);
  EXPECT_EQ(edges[2].face, 4);                    // z low ...
  EXPECT_NEAR(edges[2].position, 42.0, 1e-9);     // ... is near the bottom: (1 - 0.3) * 60
  EXPECT_NEAR(edges[3].position, 18.0, 1e-9);     // z high near the top
  dragSliceClipEdge(box, coronal, dims, 5, 6.0);  // z high edge dragged to v = 6
  EXPECT_NEAR(box.hi.z, 0.9, 1e-9);
  EXPECT_TRUE(sliceInsideClip(coronal, dims, box, 40));
  EXPECT_FALSE(sliceInsideClip(coronal, dims, box, 10));
}
