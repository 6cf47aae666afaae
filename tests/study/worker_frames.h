#pragma once
// The render worker's last frame, collected on its thread (no Post: callbacks run there), and
// a request that waits for its frame: the study tests that drive the real worker share it. A
// coarse first image (Frame::coarse: a study just opened out of core) is counted, not taken
// for the frame asked for.
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>

#include <gtest/gtest.h>

#include "render_worker.h"

namespace voxray::test {

struct WorkerFrames {
  std::mutex mutex;
  std::condition_variable arrived;
  std::shared_ptr<const Frame> last;
  int coarse = 0;  // coarse first images seen
  std::string error;
  std::chrono::seconds wait{120};  // for one frame; an error fails the test

  RenderCallbacks callbacks() {
    RenderCallbacks cb;
    cb.frame = [this](std::shared_ptr<const Frame> f) {
      std::lock_guard lock(mutex);
      if (f->coarse)
        ++coarse;
      else
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
  // Requests p and waits for its frame (WAIT at most).
  std::shared_ptr<const Frame> render(RenderWorker& w, const RenderParams& p, bool interactive) {
    std::unique_lock lock(mutex);
    last.reset();
    lock.unlock();
    w.request(p, interactive);
    lock.lock();
    arrived.wait_for(lock, wait, [&] { return last || !error.empty(); });
    EXPECT_EQ(error, "");
    return last;
  }
};

}  // namespace voxray::test
