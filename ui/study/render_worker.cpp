#include "render_worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <thread>
#include <utility>

#include "voxray/io/error.h"

namespace voxray {

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

void RenderWorker::setSegmentation(std::shared_ptr<const Segmentation> whole) {
  {
    std::lock_guard lock(mutex_);
    SegmentationUpdate u;
    u.replace = true;
    u.whole = std::move(whole);
    pendingSegmentation_ = std::move(u);
  }
  wake_.notify_all();
}

void RenderWorker::updateSegmentation(std::vector<Segment> segments, LabelPatch box) {
  {
    std::lock_guard lock(mutex_);
    if (!pendingSegmentation_) pendingSegmentation_.emplace();
    pendingSegmentation_->hasSegments = true;
    pendingSegmentation_->segments = std::move(segments);
    if (!box.empty()) pendingSegmentation_->patches.push_back(std::move(box));
  }
  wake_.notify_all();
}

void RenderWorker::request(const RenderParams& params, bool interactive, int tag, bool withHits) {
  {
    std::lock_guard lock(mutex_);
    (tag == 0 ? pendingView_ : pendingExport_) = Request{params, interactive, tag, withHits, {}, 0};
  }
  wake_.notify_all();
}

void RenderWorker::requestBands(const RenderParams& params, std::vector<RowBand> bands) {
  {
    std::lock_guard lock(mutex_);
    const int total = int(bands.size());
    pendingView_ = Request{params, false, 0, false, std::move(bands), total};
  }
  wake_.notify_all();
}

void RenderWorker::prepare(std::vector<RenderParams> params) {
  {
    std::lock_guard lock(mutex_);
    pendingPrepare_ = std::move(params);
  }
  wake_.notify_all();
}

void RenderWorker::buildLoop(ClContext& ctx) {
  // Behind the view's frames and the UI on a shared CPU: PoCL compiles on this thread.
  setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), 10);
  while (true) {
    std::string options;
    int left = 0;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return task_.cancelled() || !toBuild_.empty(); });
      if (task_.cancelled()) return;
      options = toBuild_.front();
      toBuild_.erase(toBuild_.begin());
    }
    try {
      ctx.prebuild("raycast.cl", options);
    } catch (const std::exception& e) {
      reportError(e.what(), false);  // the frame that needs it would fail alike
    }
    {
      std::lock_guard lock(mutex_);
      left = int(toBuild_.size());
    }
    if (callbacks_.preparing) task_.post([f = callbacks_.preparing, left] { f(left); });
  }
}

void RenderWorker::renderBands(Raycaster& raycaster, Request req, Image& view) {
  const RenderParams& p = req.params;
  view = upscaleNearest(view, p.width, p.height);
  Renderer& renderer = raycaster.rendererFor(p);
  FrameStats sum;
  for (size_t i = 0; i < req.bands.size(); ++i) {
    const RowBand b = req.bands[i];
    FrameStats s;
    renderer.renderRows(p, view, b.y0, b.y1, &s);
    sum.kernelMs += s.kernelMs;
    sum.totalMs += s.totalMs;
    sum.lightingMs += s.lightingMs;
    sum.variant = s.variant;
    auto frame = std::make_shared<Frame>();
    frame->image = view;
    frame->stats = sum;  // the bands' times so far
    frame->params = p;
    frame->band = b;
    frame->bands = req.bandsTotal;
    frame->bandsDone = req.bandsTotal - int(req.bands.size() - i - 1);
    if (callbacks_.frame) task_.post([f = callbacks_.frame, frame] { f(frame); });
    std::lock_guard lock(mutex_);
    if (task_.cancelled() || pendingView_ || pendingVolume_) return;  // newest camera first
    if (pendingExport_ && i + 1 < req.bands.size()) {
      req.bands.erase(req.bands.begin(), req.bands.begin() + long(i + 1));
      pendingView_ = std::move(req);  // the export first, then the bands left
      return;
    }
  }
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
  std::shared_ptr<const Volume> volume;      // kept alive while the raycaster uses it
  Image view;                                // the last view frame: banded frames paint over it
  std::optional<Segmentation> segmentation;  // the render thread's copy (setSegmentation)
  bool segShown = false;                     // the raycaster holds it
  std::thread builder;                       // prepare()'s builds; joined before ctx goes
  struct Join {
    std::thread& t;
    ~Join() {
      if (t.joinable()) t.join();  // cancelled: it ends after the build in progress
    }
  } join{builder};
  while (true) {
    std::shared_ptr<const Volume> nextVolume;
    std::optional<SegmentationUpdate> segUpdate;
    std::optional<Request> req;
    std::vector<RenderParams> prepare;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] {
        return task_.cancelled() || pendingVolume_ || pendingView_ || pendingExport_ ||
               pendingSegmentation_ || (!pendingPrepare_.empty() && raycaster);
      });
      if (task_.cancelled()) return;
      if (raycaster) prepare = std::exchange(pendingPrepare_, {});
      nextVolume = std::move(pendingVolume_);
      pendingVolume_.reset();
      segUpdate = std::move(pendingSegmentation_);
      pendingSegmentation_.reset();
      if (pendingExport_) {
        req = std::move(pendingExport_);
        pendingExport_.reset();
      } else if (!nextVolume) {
        req = std::move(pendingView_);
        pendingView_.reset();
      }
    }
    if (!ctx) continue;  // reported once above; nothing can render
    if (!prepare.empty()) {
      // The options depend on the volume on the device (storage, slabs, packets): the
      // raycaster says them here, on its own thread.
      std::vector<std::string> options;
      for (const RenderParams& p : prepare) {
        std::string o = raycaster->variantOptions(p);
        if (std::find(options.begin(), options.end(), o) == options.end()) options.push_back(o);
      }
      {
        std::lock_guard lock(mutex_);
        toBuild_ = std::move(options);
      }
      if (!builder.joinable()) builder = std::thread([this, c = ctx.get()] { buildLoop(*c); });
      wake_.notify_all();
    }
    if (nextVolume) {
      try {
        raycaster = std::make_unique<Raycaster>(*ctx, *nextVolume);
        volume = nextVolume;
        segShown = false;  // a new raycaster has none
      } catch (const std::exception& e) {
        reportError(e.what(), true);
      }
    }
    // The copy takes the update: a whole new map, or the edited boxes' labels.
    bool anyPatch = false;
    glm::ivec3 lo(0), hi(0);
    if (segUpdate) {
      if (segUpdate->replace) {
        segmentation.reset();
        if (segUpdate->whole) segmentation = *segUpdate->whole;
      }
      if (segmentation && segUpdate->hasSegments) segmentation->segments = segUpdate->segments;
      for (LabelPatch& p : segUpdate->patches) {
        if (!segmentation) break;
        try {
          swapPatch(*segmentation, p);
        } catch (const std::exception&) {  // a box of another grid's map: stale
          continue;
        }
        lo = anyPatch ? glm::min(lo, p.lo) : p.lo;
        hi = anyPatch ? glm::max(hi, p.hi) : p.hi;
        anyPatch = true;
      }
    }
    if (raycaster && (segUpdate || nextVolume)) {
      // Only a segmentation on this volume's grid is shown; another waits for its volume.
      const bool fits = segmentation && sameGrid(segmentation->grid, gridOf(*volume));
      try {
        if (!fits) {
          if (raycaster->hasSegmentation()) raycaster->clearSegmentation();
          segShown = false;
        } else if (!segShown || !segUpdate || segUpdate->replace) {
          raycaster->setSegmentation(*segmentation);
          segShown = true;
        } else {
          // The list always (colours, visibility); the labels of the boxes (inclusive ends).
          raycaster->updateSegmentation(*segmentation, anyPatch ? lo : glm::ivec3(0),
                                        anyPatch ? hi - 1 : glm::ivec3(0));
        }
      } catch (const std::exception& e) {
        segShown = false;
        reportError(e.what(), false);
      }
    }
    if (!req || !raycaster) continue;
    if (req->bands.size() > 1 || (req->bandsTotal > 1 && !req->bands.empty())) {
      try {
        renderBands(*raycaster, std::move(*req), view);
      } catch (const std::exception& e) {
        reportError(e.what(), false);
      }
      continue;
    }
    auto frame = std::make_shared<Frame>();
    frame->params = req->params;
    frame->interactive = req->interactive;
    frame->tag = req->tag;
    try {
      if (req->withHits)
        frame->image = raycaster->renderWithHits(req->params, frame->hits, &frame->stats);
      else
        raycaster->rendererFor(req->params).render(req->params, frame->image, &frame->stats);
      if (req->tag == 0) view = frame->image;
      if (callbacks_.frame) task_.post([f = callbacks_.frame, frame] { f(frame); });
    } catch (const std::exception& e) {
      reportError(e.what(), false);
    }
  }
}

}  // namespace voxray
