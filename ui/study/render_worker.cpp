#include "render_worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <thread>
#include <utility>

#include "out_of_core_view.h"
#include "voxray/engine/coarse_level.h"
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

void RenderWorker::setVolume(std::shared_ptr<const Volume> volume, bool sameSeries) {
  {
    std::lock_guard lock(mutex_);
    // A time point after a new study not yet taken still belongs to that study.
    pendingSameSeries_ = sameSeries && (!pendingVolume_ || pendingSameSeries_);
    if (!sameSeries) pendingPreload_.clear();  // another study's time points
    pendingVolume_ = std::move(volume);
  }
  wake_.notify_all();
}

void RenderWorker::setOutOfCore(OutOfCoreSettings settings) {
  {
    std::lock_guard lock(mutex_);
    pendingOutOfCore_ = settings;
  }
  wake_.notify_all();
}

std::unique_ptr<RenderWorker::OutOfCoreShown> RenderWorker::openOutOfCore(
    ClContext& ctx, std::shared_ptr<const Volume> volume, size_t budget,
    const OutOfCoreSettings& settings) {
  auto o = std::make_unique<OutOfCoreShown>();
  o->volume = std::move(volume);
  o->budgetBytes = budget;
  // The study lies in host memory already: its slices are read from there part by part.
  o->source = volumeSlabSource(*o->volume);
  OutOfCoreOptions options;
  options.budgetBytes = budget;
  options.partSlices = settings.partSlices;
  options.faultDeviceParts = settings.faultDeviceParts;
  o->renderer = std::make_unique<OutOfCoreRenderer>(ctx, *o->source, options);
  return o;
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
    // Assigned, not emplace()d: clang decides the nested type is not default-constructible
    // where std::optional is instantiated, inside the still incomplete class.
    if (!pendingSegmentation_) pendingSegmentation_ = SegmentationUpdate{};
    pendingSegmentation_->hasSegments = true;
    pendingSegmentation_->segments = std::move(segments);
    if (!box.empty()) pendingSegmentation_->patches.push_back(std::move(box));
  }
  wake_.notify_all();
}

void RenderWorker::setOverlay(std::shared_ptr<const Volume> overlay, TransferFunction tf) {
  {
    std::lock_guard lock(mutex_);
    pendingOverlay_ = OverlayUpdate{std::move(overlay), std::move(tf)};
  }
  wake_.notify_all();
}

void RenderWorker::preload(VolumeSeries series) {
  {
    std::lock_guard lock(mutex_);
    pendingPreload_ = std::move(series);
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

Image RenderWorker::renderOnDevice(const RenderParams& params, const Volume* volume) {
  auto job = std::make_shared<OnDevice>();
  job->params = params;
  job->volume = volume;
  std::future<Image> image = job->image.get_future();
  {
    std::lock_guard lock(mutex_);
    if (task_.cancelled())
      throw Error(Error::Kind::Device, "the 3D view's renderer has stopped: export again");
    pendingOnDevice_.push_back(job);
  }
  wake_.notify_all();
  try {
    return image.get();
  } catch (const std::future_error&) {  // the worker ended with the request still queued
    throw Error(Error::Kind::Device, "the 3D view's renderer has stopped: export again");
  }
}

void RenderWorker::requestBands(const RenderParams& params, std::vector<RowBand> bands) {
  {
    std::lock_guard lock(mutex_);
    const int total = int(bands.size());
    pendingView_ = Request{params, false, 0, false, std::move(bands), total};
  }
  wake_.notify_all();
}

void RenderWorker::requestBackground(std::vector<std::pair<int, RenderParams>> frames) {
  {
    std::lock_guard lock(mutex_);
    pendingBackground_ = std::move(frames);
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

void RenderWorker::previewCoarse(ClContext& ctx, const Volume& volume,
                                 const std::optional<RenderParams>& lastView) {
  std::optional<RenderParams> params;
  {
    std::lock_guard lock(mutex_);
    if (pendingView_) params = pendingView_->params;  // the new study's view, when asked yet
  }
  if (!params) params = lastView;
  if (!params || !callbacks_.frame) return;
  try {
    // 4x (8x above 32 M voxels at 4x: a 2048 x 2048 x 1024 volume), a box mean: see
    // coarse_level.h for why not a max.
    const Volume level = coarseLevel(volume, coarseFactorFor(volume, size_t(1) << 25) < 8 ? 4 : 8);
    Raycaster preview(ctx, level);
    auto frame = std::make_shared<Frame>();
    frame->params = *params;
    frame->coarse = true;
    frame->volume = &volume;
    preview.rendererFor(*params).render(*params, frame->image, &frame->stats);
    task_.post([f = callbacks_.frame, frame] { f(frame); });
  } catch (const std::exception&) {
    // No preview: the full upload that follows renders or says what is wrong.
  }
}

void RenderWorker::renderBands(Raycaster& raycaster, Request req, Image& view,
                               const Volume* volume) {
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
    frame->volume = volume;
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

void RenderWorker::selectTimePoint(ClContext& ctx, const std::shared_ptr<const Volume>& next,
                                   std::vector<Uploaded>& uploaded, VolumeResidency& residency,
                                   Raycaster*& shown) const {
  auto find = [&](const void* key) {
    return std::find_if(uploaded.begin(), uploaded.end(),
                        [&](const Uploaded& u) { return u.volume.get() == key; });
  };
  const VolumeResidency::Use use = residency.use(next.get(), next->byteSize());
  for (const void* key : use.evict) {
    auto it = find(key);
    if (it != uploaded.end() && it->raycaster.get() != shown) uploaded.erase(it);
  }
  auto it = find(next.get());
  if (it == uploaded.end()) {
    try {
      uploaded.push_back({next, std::make_unique<Raycaster>(ctx, *next)});
      it = std::prev(uploaded.end());
    } catch (const std::exception& e) {
      // The time point shown stays on screen (no study to undo).
      residency.forget(next.get());
      reportError(e.what(), false);
    }
  }
  if (it != uploaded.end()) shown = it->raycaster.get();
  // The raycaster shown before may have been over the budget: released once replaced.
  std::erase_if(uploaded, [&](const Uploaded& u) {
    return u.raycaster.get() != shown && !residency.resident(u.volume.get());
  });
}

bool RenderWorker::busy() {
  std::lock_guard lock(mutex_);
  return working_ || pendingVolume_ || pendingView_ || pendingExport_ || pendingSegmentation_ ||
         pendingOverlay_ || pendingOutOfCore_ || !pendingOnDevice_.empty();
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
  // The uploaded volumes (one, or time points of a 4D series), each kept alive while its
  // raycaster uses it; RAYCASTER renders the one shown.
  std::vector<Uploaded> uploaded;
  Raycaster* raycaster = nullptr;
  std::unique_ptr<VolumeResidency> residency;
  std::optional<RenderParams> lastView;      // the last view frame's: time points warm up with it
  Image view;                                // the last view frame: banded frames paint over it
  std::optional<Segmentation> segmentation;  // the render thread's copy (setSegmentation)
  const Raycaster* segOn = nullptr;          // the raycaster holding it (time points: one each)
  std::optional<OverlayUpdate> overlay;      // the render thread's (setOverlay)
  const Raycaster* overlayOn = nullptr;      // the raycaster holding it
  std::thread builder;                       // prepare()'s builds; joined before ctx goes
  OutOfCoreSettings oocSettings;             // setOutOfCore's
  std::unique_ptr<OutOfCoreShown> ooc;       // the study drawn out of core (raycaster null)
  struct Join {
    std::thread& t;
    ~Join() {
      if (t.joinable()) t.join();  // cancelled: it ends after the build in progress
    }
  } join{builder};
  // A frame made for REQ: to the background callback, or shown (a view frame is kept: banded
  // frames paint over it, time points warm up with its parameters).
  auto deliver = [&](const Request& r, const std::shared_ptr<Frame>& frame) {
    if (r.background) {
      if (callbacks_.background) task_.post([f = callbacks_.background, frame] { f(frame); });
      return;
    }
    if (r.tag == 0) {
      view = frame->image;
      lastView = r.params;
    }
    if (callbacks_.frame) task_.post([f = callbacks_.frame, frame] { f(frame); });
  };
  while (true) {
    std::shared_ptr<const Volume> nextVolume, ahead;
    bool sameSeries = false;
    std::optional<SegmentationUpdate> segUpdate;
    std::optional<OverlayUpdate> overlayUpdate;
    std::optional<Request> req;
    std::vector<RenderParams> prepare;
    std::shared_ptr<OnDevice> onDevice;
    std::optional<OutOfCoreSettings> oocUpdate;
    {
      std::unique_lock lock(mutex_);
      working_ = false;
      wake_.wait(lock, [&] {
        return task_.cancelled() || pendingVolume_ || pendingView_ || pendingExport_ ||
               pendingSegmentation_ || pendingOverlay_ ||
               (!pendingPrepare_.empty() && (raycaster || ooc)) ||
               (!pendingPreload_.empty() && raycaster) || pendingOutOfCore_ ||
               (!pendingBackground_.empty() && (raycaster || ooc)) || !pendingOnDevice_.empty();
      });
      if (task_.cancelled()) return;
      working_ = true;
      if (raycaster) {
        prepare = std::exchange(pendingPrepare_, {});
      } else if (ooc && !pendingPrepare_.empty()) {
        // The Raycaster's variants: none to build for an out-of-core study (its part kernels
        // build with its first frames); the status says none are left.
        pendingPrepare_.clear();
        if (callbacks_.preparing) task_.post([f = callbacks_.preparing] { f(0); });
      }
      if (!pendingOnDevice_.empty()) {
        onDevice = std::move(pendingOnDevice_.front());
        pendingOnDevice_.erase(pendingOnDevice_.begin());
      }
      nextVolume = std::move(pendingVolume_);
      sameSeries = pendingSameSeries_;
      pendingVolume_.reset();
      segUpdate = std::move(pendingSegmentation_);
      pendingSegmentation_.reset();
      overlayUpdate = std::move(pendingOverlay_);
      pendingOverlay_.reset();
      oocUpdate = pendingOutOfCore_;
      pendingOutOfCore_.reset();
      if (pendingExport_) {
        req = std::move(pendingExport_);
        pendingExport_.reset();
      } else if (!nextVolume) {
        req = std::move(pendingView_);
        pendingView_.reset();
      }
      if (!req && !nextVolume && (raycaster || ooc) && !pendingBackground_.empty()) {
        auto& [tag, params] = pendingBackground_.front();
        req = Request{std::move(params), false, tag, false, {}, 0, true};
        pendingBackground_.erase(pendingBackground_.begin());
      }
      // Only when nothing else waits: one time point to upload ahead.
      if (!nextVolume && !req && raycaster && !pendingPreload_.empty()) {
        ahead = std::move(pendingPreload_.front());
        pendingPreload_.erase(pendingPreload_.begin());
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
    if (oocUpdate && !(*oocUpdate == oocSettings)) {
      oocSettings = *oocUpdate;
      // The study shown opens again when it moves into or out of core, or its budget changes
      // (in core to in core: nothing to do). A 4D series' time points stay as they are.
      std::shared_ptr<const Volume> study = ooc                    ? ooc->volume
                                            : uploaded.size() == 1 ? uploaded.front().volume
                                                                   : nullptr;
      if (study && !nextVolume) {
        const OutOfCoreChoice c = chooseOutOfCore(study->byteSize(), ctx->device().globalMemBytes,
                                                  oocSettings.budgetBytes);
        if (c.outOfCore || ooc) {
          nextVolume = study;
          sameSeries = false;
        }
      }
    }
    if (nextVolume) {
      if (!residency)
        residency = std::make_unique<VolumeResidency>(
            residencyBudget(ctx->device().isGpu, ctx->device().globalMemBytes));
      const size_t globalMem = ctx->device().globalMemBytes;
      const OutOfCoreChoice choice =
          chooseOutOfCore(nextVolume->byteSize(), globalMem, oocSettings.budgetBytes);
      // Out of core in place of the study shown (a failure leaves an in-core study rendering;
      // an out-of-core one leaves the device first, below, so that its parts make room).
      auto openOoc = [&](size_t budget) {
        auto next = openOutOfCore(*ctx, nextVolume, budget, oocSettings);
        raycaster = nullptr;
        uploaded.clear();
        residency->clear();
        ooc = std::move(next);
      };
      if (!sameSeries && choice.outOfCore) {
        try {
          ooc.reset();  // its parts leave the device before the next study's come
          openOoc(choice.budgetBytes);
        } catch (const std::exception& e) {
          reportError(e.what(), true);
        }
      } else if (!sameSeries) {
        // Another study: it replaces every volume uploaded, once it is on the device (a
        // failed upload leaves the last study rendering).
        if (nextVolume->byteSize() >= kCoarsePreviewBytes)
          previewCoarse(*ctx, *nextVolume, lastView);
        try {
          auto next = std::make_unique<Raycaster>(*ctx, *nextVolume);
          raycaster = nullptr;
          ooc.reset();
          uploaded.clear();
          residency->clear();
          residency->use(nextVolume.get(), nextVolume->byteSize());
          uploaded.push_back({nextVolume, std::move(next)});
          raycaster = uploaded.back().raycaster.get();
        } catch (const Error& e) {
          if (e.kind() != Error::Kind::Device) {
            reportError(e.what(), true);
          } else {
            // The device could not take it whole (it holds less than it said, or other
            // programs hold part of it): out of core within what the headroom leaves.
            try {
              openOoc(chooseOutOfCore(SIZE_MAX, globalMem, 0).budgetBytes);
            } catch (const std::exception& e2) {
              reportError(std::string(e.what()) + "; out of core: " + e2.what(), true);
            }
          }
        } catch (const std::exception& e) {
          reportError(e.what(), true);
        }
      } else {
        selectTimePoint(*ctx, nextVolume, uploaded, *residency, raycaster);
        if (raycaster) ooc.reset();  // a time point of a series: in core (the worker's rule)
      }
    }
    if (ahead && residency && residency->preload(ahead.get(), ahead->byteSize())) {
      try {
        uploaded.push_back({ahead, std::make_unique<Raycaster>(*ctx, *ahead)});
        // The first frame on a new raycaster costs as much as the upload again (PoCL CPU,
        // 512x512x256: upload 554 ms, first frame 426 ms, the next 2.4 ms): a tiny frame
        // with the view's parameters pays it here, not the first frame the user sees.
        if (lastView) {
          RenderParams tiny = *lastView;
          tiny.width = tiny.height = 8;
          Image scratch;
          uploaded.back().raycaster->rendererFor(tiny).render(tiny, scratch);
        }
      } catch (const std::exception&) {
        // Not uploaded ahead: switching to it uploads it then (and says why if it fails).
        residency->forget(ahead.get());
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
      const Volume* volume = nullptr;
      for (const Uploaded& u : uploaded)
        if (u.raycaster.get() == raycaster) volume = u.volume.get();
      // Only a segmentation on this volume's grid is shown; another waits for its volume.
      const bool fits = volume && segmentation && sameGrid(segmentation->grid, gridOf(*volume));
      try {
        if (!fits) {
          if (raycaster->hasSegmentation()) raycaster->clearSegmentation();
          segOn = nullptr;
        } else if (nextVolume || raycaster != segOn || !segUpdate || segUpdate->replace) {
          // A new volume or time point (each has its own raycaster), or a whole new map.
          raycaster->setSegmentation(*segmentation);
          segOn = raycaster;
        } else {
          // The list always (colours, visibility); the labels of the boxes (inclusive ends).
          // (No box: an empty one, lo above hi, so no surface field counts as edited.)
          raycaster->updateSegmentation(*segmentation, anyPatch ? lo : glm::ivec3(1),
                                        anyPatch ? hi - 1 : glm::ivec3(0));
        }
      } catch (const std::exception& e) {
        segOn = nullptr;
        reportError(e.what(), false);
      }
    }
    const bool newOverlay = overlayUpdate.has_value();
    if (newOverlay) overlay = std::move(overlayUpdate);
    // A new raycaster may reuse a freed one's address: a new volume sets it again.
    if (newOverlay || nextVolume) overlayOn = nullptr;
    if (raycaster && raycaster != overlayOn) {
      // Each raycaster (a time point) holds its own copy of the overlay on the device.
      overlayOn = raycaster;
      try {
        if (overlay && overlay->volume)
          raycaster->setOverlay(*overlay->volume, overlay->tf);  // warnings: FusionModel's
        else if (raycaster->hasOverlay())
          raycaster->clearOverlay();
      } catch (const std::exception& e) {
        reportError(e.what(), false);
      }
    }
    // An out-of-core frame of ASKED into FRAME: a preview (the parts on the device, the
    // others coarse) or converged; what the renderer does not draw is off, and said.
    auto drawOutOfCore = [&](const RenderParams& asked, bool preview, Frame& frame) {
      const bool labels = segmentation && !segmentation->segments.empty() &&
                          sameGrid(segmentation->grid, gridOf(*ooc->volume));
      const bool fused = overlay && overlay->volume;
      const OutOfCoreParams o = outOfCoreParams(asked, labels, fused, ooc->volume->spacingMm.z);
      OutOfCoreStats s;
      if (preview)
        ooc->renderer->preview(o.params, frame.image, &s);
      else
        ooc->renderer->render(o.params, frame.image, &s);
      frame.outOfCore = true;
      frame.outOfCoreStats = s;
      frame.stats.totalMs = s.totalMs;
      frame.resolutionNote = resolutionNote(s);
      frame.limitsNote = limitsNote(o.off);
    };
    if (onDevice && ooc && onDevice->volume == ooc->volume.get()) {
      try {
        Frame f;
        drawOutOfCore(onDevice->params, false, f);
        onDevice->image.set_value(std::move(f.image));
      } catch (...) {
        onDevice->image.set_exception(std::current_exception());
      }
      onDevice.reset();
    }
    if (onDevice) {
      // The raycaster that holds its volume, lit as a still frame: the image a raycaster of
      // its own would render.
      const auto u = std::find_if(uploaded.begin(), uploaded.end(), [&](const Uploaded& each) {
        return each.volume.get() == onDevice->volume;
      });
      try {
        if (u == uploaded.end())
          throw Error(Error::Kind::Device,
                      "the volume is no longer on the device (another study was opened): "
                      "export again");
        u->raycaster->holdLightGrid(false);
        onDevice->image.set_value(
            u->raycaster->rendererFor(onDevice->params).render(onDevice->params));
      } catch (...) {
        onDevice->image.set_exception(std::current_exception());
      }
    }
    if (req && ooc && !raycaster) {
      auto frame = std::make_shared<Frame>();
      frame->params = req->params;
      frame->interactive = req->interactive;
      frame->tag = req->tag;
      frame->volume = ooc->volume.get();
      try {
        if (req->withHits)
          throw Error(Error::Kind::Input,
                      "picking in 3D needs the volume on the device whole: it is drawn out of "
                      "core; raise or clear the GPU memory budget (Render panel, Quality) to pick");
        // A study just opened holds no part yet: its first image is a preview (the coarse
        // level, uploading nothing) shown at once, the converged frame after it.
        if (!req->interactive && req->tag == 0 && !req->background &&
            ooc->renderer->residentCount() == 0 && callbacks_.frame) {
          auto first = std::make_shared<Frame>(*frame);
          first->coarse = true;
          drawOutOfCore(req->params, true, *first);
          task_.post([f = callbacks_.frame, first] { f(first); });
        }
        // The bands of a sharp frame are not split here: one converged frame.
        drawOutOfCore(req->params, req->interactive, *frame);
        deliver(*req, frame);
      } catch (const std::exception& e) {
        reportError(e.what(), false);
      }
      continue;
    }
    if (!req || !raycaster) continue;
    // A drag's frames keep the shadows grid of its start (issue 40 item 4); the first frame
    // after it rebuilds for its light: the still frame as ever.
    raycaster->holdLightGrid(req->interactive);
    const Volume* shown = nullptr;
    for (const Uploaded& u : uploaded)
      if (u.raycaster.get() == raycaster) shown = u.volume.get();
    if (req->bands.size() > 1 || (req->bandsTotal > 1 && !req->bands.empty())) {
      try {
        renderBands(*raycaster, std::move(*req), view, shown);
      } catch (const std::exception& e) {
        reportError(e.what(), false);
      }
      continue;
    }
    auto frame = std::make_shared<Frame>();
    frame->params = req->params;
    frame->interactive = req->interactive;
    frame->tag = req->tag;
    frame->volume = shown;
    try {
      if (req->withHits)
        frame->image = raycaster->renderWithHits(req->params, frame->hits, &frame->stats);
      else
        raycaster->rendererFor(req->params).render(req->params, frame->image, &frame->stats);
      deliver(*req, frame);
    } catch (const std::exception& e) {
      reportError(e.what(), false);
    }
  }
}

}  // namespace voxray
