#pragma once
// Thick-slab images off the GUI thread: a 20 mm slab of a 512x512x400 CT takes most of a
// second to resample, too long to block a slice view. request() returns at once and the
// image arrives through DONE (on the Post's thread). Newest wins: requests made while one
// renders collapse into the last, and a result for a replaced or dropped request is thrown
// away, so a view never shows an image older than the one it asked for.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>

#include "background_task.h"
#include "no_qt.h"
#include "slice_image.h"

namespace voxray {

struct SlabRequest {
  std::shared_ptr<const Volume> volume;  // kept alive while the image renders
  PlaneGrid plane;
  WindowLevel wl;
  Interp interp = Interp::Linear;
  Slab slab;
};

class SlabRenderer {
 public:
  using Done = std::function<void(Image)>;
  explicit SlabRenderer(Done done, BackgroundTask::Post post = {})
      : done_(std::move(done)), task_(std::move(post)) {}
  ~SlabRenderer() { drop(); }  // then task_ waits for an image in flight

  // Renders REQUEST (renderPlane) in the background; replaces any request not yet started.
  void request(SlabRequest request);
  // Forgets the pending request and any result in flight (the view went thin, or closed).
  void drop();

 private:
  void run();  // the job: renders pending requests until none is left

  Done done_;
  std::mutex mutex_;
  std::optional<SlabRequest> pending_;
  uint64_t pendingGeneration_ = 0;
  bool running_ = false;
  std::atomic<uint64_t> generation_{0};  // the newest request; older results are stale
  BackgroundTask task_;                  // last member: stops before the rest goes
};

}  // namespace voxray
