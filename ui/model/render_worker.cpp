#include "render_worker.h"

#include "voxray/engine/cl_context.h"
#include "voxray/io/error.h"

namespace voxray::ui {

RenderWorker::RenderWorker(std::string device, RenderCallbacks callbacks, BackgroundTask::Post post)
    : device_(std::move(device)), callbacks_(std::move(callbacks)), task_(std::move(post)) {
  task_.start([this] { run(); });
}

RenderWorker::~RenderWorker() {
  {
    std::lock_guard lock(mutex_);  // the loop checks the flag under the lock before waiting
    task_.cancel();
  }
  wake_.notify_all();
  task_.wait();
}

void RenderWorker::setVolume(std::shared_ptr<const Volume> volume) {
  {
    std::lock_guard lock(mutex_);
    pendingVolume_ = std::move(volume);
  }
  wake_.notify_all();
}

void RenderWorker::request(const RenderParams& params, bool interactive, int tag, bool withHits) {
  {
    std::lock_guard lock(mutex_);
    (tag == 0 ? pendingView_ : pendingExport_) = Request{params, interactive, tag, withHits};
  }
  wake_.notify_all();
}

void RenderWorker::reportError(const std::string& message, bool volumeRejected) const {
  if (callbacks_.error)
    task_.post([f = callbacks_.error, message, volumeRejected] { f(message, volumeRejected); });
}

void RenderWorker::run() {
  std::unique_ptr<ClContext> ctx;
  try {
    ctx = std::make_unique<ClContext>(device_);
    if (callbacks_.deviceReady)
      task_.post([f = callbacks_.deviceReady, name = ctx->device().name] { f(name); });
  } catch (const std::exception& e) {
    reportError(e.what(), false);
  }
  std::unique_ptr<Raycaster> raycaster;
  std::shared_ptr<const Volume> volume;  // kept alive while the raycaster uses it
  Image reuse;
  while (true) {
    std::shared_ptr<const Volume> nextVolume;
    std::optional<Request> req;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] {
        return task_.cancelled() || pendingVolume_ || pendingView_ || pendingExport_;
      });
      if (task_.cancelled()) return;
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
        reportError(e.what(), true);
      }
    }
    if (!req || !raycaster) continue;
    auto frame = std::make_shared<Frame>();
    frame->params = req->params;
    frame->interactive = req->interactive;
    frame->tag = req->tag;
    try {
      if (req->withHits)
        frame->image = raycaster->renderWithHits(req->params, frame->hits, &frame->stats);
      else
        raycaster->render(req->params, frame->image, &frame->stats);
      if (callbacks_.frame) task_.post([f = callbacks_.frame, frame] { f(frame); });
    } catch (const std::exception& e) {
      reportError(e.what(), false);
    }
  }
}

}  // namespace voxray::ui
