#include "render_worker.h"

#include "voxray/engine/cl_context.h"
#include "voxray/io/error.h"

namespace voxray::ui {

RenderWorker::RenderWorker(std::string device, RenderCallbacks callbacks)
    : device_(std::move(device)), callbacks_(std::move(callbacks)) {
  thread_ = std::thread([this] { run(); });
}

RenderWorker::~RenderWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void RenderWorker::setVolume(std::shared_ptr<const Volume> volume) {
  {
    std::lock_guard lock(mutex_);
    pendingVolume_ = std::move(volume);
  }
  wake_.notify_all();
}

void RenderWorker::request(const RenderParams& params, bool interactive, int tag) {
  {
    std::lock_guard lock(mutex_);
    (tag == 0 ? pendingView_ : pendingExport_) = Request{params, interactive, tag};
  }
  wake_.notify_all();
}

void RenderWorker::run() {
  std::unique_ptr<ClContext> ctx;
  try {
    ctx = std::make_unique<ClContext>(device_);
    if (callbacks_.deviceReady) callbacks_.deviceReady(ctx->device().name);
  } catch (const std::exception& e) {
    if (callbacks_.error) callbacks_.error(e.what(), false);
  }
  std::unique_ptr<Raycaster> raycaster;
  std::shared_ptr<const Volume> volume;  // kept alive while the raycaster uses it
  Image reuse;
  while (true) {
    std::shared_ptr<const Volume> nextVolume;
    std::optional<Request> req;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || pendingVolume_ || pendingView_ || pendingExport_; });
      if (stop_) return;
      nextVolume = std::move(pendingVolume_);
      pendingVolume_.reset();
      if (pendingExport_) {
        req = std::move(pendingExport_);
        pendingExport_.reset();
      } else if (!nextVolume) {
        req = std::move(pendingView_);
        pendingView_.reset();
      }
    }
    if (!ctx) continue;  // reported once above; nothing can render
    if (nextVolume) {
      try {
        raycaster = std::make_unique<Raycaster>(*ctx, *nextVolume);
        volume = nextVolume;
      } catch (const std::exception& e) {
        if (callbacks_.error) callbacks_.error(e.what(), true);
      }
    }
    if (!req || !raycaster) continue;
    auto frame = std::make_shared<Frame>();
    frame->params = req->params;
    frame->interactive = req->interactive;
    frame->tag = req->tag;
    try {
      raycaster->render(req->params, frame->image, &frame->stats);
      if (callbacks_.frame) callbacks_.frame(frame);
    } catch (const std::exception& e) {
      if (callbacks_.error) callbacks_.error(e.what(), false);
    }
  }
}

}  // namespace voxray::ui
