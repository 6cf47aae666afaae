// The workstation's drag with shadows (issue 40 item 4): the render worker holds the light
// grid for its interactive frames (the light follows the camera: a grid build per frame
// otherwise) and the first still frame after them is the still frame of a raycaster that
// never held, byte for byte.
#include <gtest/gtest.h>

#include "render_worker.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/phantom.h"
#include "worker_frames.h"

using namespace voxray;

using Frames = test::WorkerFrames;

TEST(ShadowDragWorker, DragFramesBuildNoGridAndTheStillFrameAfterIsUnchanged) {
  auto volume = std::make_shared<const Volume>(makeHeadPhantom(48));
  Frames frames;
  RenderWorker worker("cpu", frames.callbacks());
  worker.setVolume(volume);
  RenderParams p;
  p.width = 48;
  p.height = 36;
  p.mode = Mode::Dvr;
  p.lighting = Lighting::Shadows;  // the light follows the camera (the default)
  auto f = frames.render(worker, p, false);
  ASSERT_TRUE(f);
  EXPECT_GT(f->stats.lightingMs, 0.0);  // the still frame builds its grid
  RenderParams drag = p;
  for (int i = 1; i <= 5; ++i) {
    drag.camera.azimuthDeg = 2.0 * i;  // the 3D view's drag turns the camera and its light
    f = frames.render(worker, drag, true);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->stats.lightingMs, 0.0) << "drag frame " << i;
  }
  f = frames.render(worker, drag, false);  // released
  ASSERT_TRUE(f);
  EXPECT_GT(f->stats.lightingMs, 0.0);  // the grid of its own light
  ClContext ctx("cpu");
  Raycaster fresh(ctx, *volume);
  const Image still = fresh.render(drag);
  ASSERT_EQ(f->image.rgba.size(), still.rgba.size());
  EXPECT_TRUE(f->image.rgba == still.rgba);
}
