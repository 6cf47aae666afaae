// The workstation's drag with shadows (issue 40 item 4): the render worker holds the light
// grid for its interactive frames (the light follows the camera: a grid build per frame
// otherwise) and the first still frame after them is the still frame of a raycaster that
// never held, byte for byte.
#include <condition_variable>
#include <mutex>

#include <gtest/gtest.h>

#include "render_worker.h"
#include "voxray/engine/cl_context.h"
#include "voxray/engine/raycaster.h"
#include "voxray/io/phantom.h"

using namespace voxray;

namespace {

// The worker's frames, collected on its thread (no Post: callbacks run there).
struct Frames {
  std::mutex mutex;
  std::condition_variable arrived;
  std::shared_ptr<const Frame> last;
  std::string error;
  RenderCallbacks callbacks() {
    RenderCallbacks cb;
    cb.frame = [this](std::shared_ptr<const Frame> f) {
      std::lock_guard lock(mutex);
      last = std::move(f);
      arrived.notify_all();
    };
    cb.error = [this](const std::string& m, bool) {
      std::lock_guard lock(mutex);
      error = m;
      arrived.notify_all();
    };
    return cb;
  }
  std::shared_ptr<const Frame> render(RenderWorker& w, const RenderParams& p, bool interactive) {
    std::unique_lock lock(mutex);
    last.reset();
    lock.unlock();
    w.request(p, interactive);
    lock.lock();
    arrived.wait_for(lock, std::chrono::seconds(120), [&] { return last || !error.empty(); });
    EXPECT_EQ(error, "");
    return last;
  }
};

}  // namespace

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
