#include "slab_render.h"

namespace voxray {

void SlabRenderer::request(SlabRequest request) {
  {
    std::lock_guard lock(mutex_);
    pending_ = std::move(request);
    pendingGeneration_ = ++generation_;
    if (running_) return;  // the running job takes it next
    running_ = true;
  }
  task_.start([this] { run(); });  // the previous job has returned: joins at once
}

void SlabRenderer::drop() {
  std::lock_guard lock(mutex_);
  pending_.reset();
  ++generation_;
}

void SlabRenderer::run() {
  for (;;) {
    SlabRequest r;
    uint64_t generation = 0;
    {
      std::lock_guard lock(mutex_);
      if (!pending_ || task_.cancelled()) {
        running_ = false;
        return;
      }
      r = std::move(*pending_);
      pending_.reset();
      generation = pendingGeneration_;
    }
    Image image = renderPlane(*r.volume, r.plane, r.wl, r.interp, r.slab);
    if (generation != generation_) continue;  // replaced while rendering
    task_.post([this, generation, image = std::move(image)]() mutable {
      if (generation == generation_) done_(std::move(image));
    });
  }
}

}  // namespace voxray
