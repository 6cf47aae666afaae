// Lighting cinematic in the 3D view: frames from the real render worker (PoCL) accumulate
// path samples while the view is still; any change of the frame restarts the count.
#include <gtest/gtest.h>

#include "progressive_render.h"
#include "render_worker.h"
#include "voxray/io/phantom.h"
#include "worker_frames.h"

using namespace voxray;

using Frames = test::WorkerFrames;

TEST(ProgressiveRender, StillFramesAccumulateAndAnyChangeRestartsTheCount) {
  Frames frames;
  RenderWorker worker("cpu", frames.callbacks());
  worker.setVolume(std::make_shared<const Volume>(makeHeadPhantom(32)));
  RenderParams p;
  p.width = 32;
  p.height = 24;
  p.mode = Mode::Dvr;
  p.lighting = Lighting::Cinematic;
  ProgressiveRender model;
  for (int pass = 1; pass <= 3; ++pass) {
    auto f = frames.render(worker, p, false);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->stats.pathSamples, pass);
    EXPECT_TRUE(model.onFrame(f->params, false, f->stats.pathSamples, f->stats.pathSeconds));
  }
  EXPECT_EQ(model.samples(), 3);
  EXPECT_EQ(model.restarts(), 0);  // a first count is not a restart
  // Each change of the frame starts again at one sample.
  RenderParams turned = p, lit = p, clipped = p;
  turned.camera.azimuthDeg = 40.0;
  lit.light.position.x = -0.5;
  clipped.clip.lo.x = 0.3;
  int restarts = model.restarts();
  for (const RenderParams& q : {turned, lit, clipped}) {
    auto f = frames.render(worker, q, false);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->stats.pathSamples, 1);
    EXPECT_TRUE(model.onFrame(f->params, false, f->stats.pathSamples, f->stats.pathSeconds));
    EXPECT_EQ(model.restarts(), ++restarts);
    EXPECT_EQ(model.statusText().rfind("cinematic: 1 sample · ", 0), 0u) << model.statusText();
  }
  // A drag frame is shown but asks for no next pass; a phong frame ends the progress.
  auto f = frames.render(worker, clipped, true);
  EXPECT_FALSE(model.onFrame(f->params, true, f->stats.pathSamples, f->stats.pathSeconds));
  EXPECT_EQ(model.samples(), 2);
  RenderParams phong = p;
  phong.lighting = Lighting::Phong;
  f = frames.render(worker, phong, false);
  EXPECT_FALSE(model.onFrame(f->params, false, f->stats.pathSamples, f->stats.pathSeconds));
  EXPECT_FALSE(model.active());
  EXPECT_EQ(model.statusText(), "");
}

TEST(ProgressiveRender, StopsAtTheSampleBudget) {
  ProgressiveRender model;
  RenderParams p;
  p.lighting = Lighting::Cinematic;
  EXPECT_TRUE(model.onFrame(p, false, ProgressiveRender::kMaxSamples - 1, 10.0));
  EXPECT_FALSE(model.onFrame(p, false, ProgressiveRender::kMaxSamples, 10.5));
  EXPECT_EQ(model.statusText(), "cinematic: 1024 samples · 10.5 s (done)");
}
