// Raycaster::rendererFor: the one place that chooses a frame's renderer (issue 33).
#include <gtest/gtest.h>

#include "path_test_scenes.h"
#include "stability_helpers.h"
#include "voxray/engine/path_tracer.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/error.h"

namespace voxray {
namespace {

TEST(RendererChoice, CinematicFramesGoToThePathTracerOthersToTheRaycaster) {
  Volume v = test::ballVolume();
  Raycaster rc(test::pocl(), v);
  RenderParams p = test::ballParams();
  for (Lighting l : {Lighting::Phong, Lighting::Shadows, Lighting::Ao}) {
    p.lighting = l;
    Renderer& r = rc.rendererFor(p);
    EXPECT_EQ(&r, static_cast<Renderer*>(&rc)) << toString(l);
    EXPECT_FALSE(r.progressive());
    // The raycaster's own frame, byte for byte.
    FrameStats s;
    Image chosen = r.render(p, &s);
    EXPECT_EQ(chosen.rgba, rc.render(p).rgba) << toString(l);
    EXPECT_EQ(s.pathSamples, 0);
    EXPECT_NE(s.variant, "path_trace");
  }
  p.lighting = Lighting::Cinematic;
  Renderer& r = rc.rendererFor(p);
  EXPECT_NE(&r, static_cast<Renderer*>(&rc));
  EXPECT_TRUE(r.progressive());
  EXPECT_EQ(&rc.rendererFor(p), &r);  // the same path tracer every frame: it accumulates
  FrameStats s;
  Image pass = r.render(p, &s);
  EXPECT_EQ(s.variant, "path_trace");
  EXPECT_EQ(s.pathSamples, 1);
  // A path tracer of its own with the same (default) options gives the same first pass.
  PathTracer pt(rc);
  Image own;
  pt.accumulate(p, 1, own);
  EXPECT_EQ(pass.rgba, own.rgba);
  // A still of 3 samples: the path tracer's run, from a fresh start.
  FrameStats still;
  Image img;
  r.renderStill(p, StillBudget{3, 0.0}, img, &still);
  EXPECT_EQ(still.pathSamples, 3);
  EXPECT_GT(still.totalMs, 0.0);
  PathTracer three(rc);
  Image ownThree;
  three.run(p, 3, 0.0, ownThree);
  EXPECT_EQ(img.rgba, ownThree.rgba);
}

TEST(RendererChoice, RaycasterAskedForACinematicFrameSaysWhereItGoes) {
  Volume v = test::ballVolume();
  Raycaster rc(test::pocl(), v);
  RenderParams p = test::ballParams();
  p.lighting = Lighting::Cinematic;
  try {
    rc.render(p);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("rendererFor"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cinematic"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace voxray
