#include "render_scheduler.h"

#include "gui_post.h"
#include "surface_pick.h"

namespace voxray::ui {

namespace {
// No movement for this long counts as "stopped". The sharp frame comes in bands that a move
// abandons within one band, so refining early costs a resumed drag at most one band's wait.
constexpr int kSettleMs = 60;
constexpr int kPickTag = 2;  // Frame::tag of a frame rendered for a 3D pick
}  // namespace

RenderScheduler::RenderScheduler(RenderStateModel& state, VolumeDocument& doc,
                                 const QString& device, QObject* parent)
    : QObject(parent),
      state_(state),
      doc_(doc),
      adaptive_(state.quality().dragFps, dragPresetSetting()) {
  qRegisterMetaType<std::shared_ptr<const Frame>>("std::shared_ptr<const voxray::Frame>");
  settle_.setSingleShot(true);
  settle_.setInterval(kSettleMs);
  connect(&settle_, &QTimer::timeout, this, [this] {
    interacting_ = false;
    requestFrame();
  });
  clock_.start();
  // The worker's callbacks arrive on this object's (the UI) thread.
  RenderCallbacks cb;
  cb.frame = [this](std::shared_ptr<const Frame> f) { onFrame(std::move(f)); };
  cb.error = [this](const std::string& message, bool rejected) {
    emit renderError(QString::fromStdString(message), rejected);
  };
  cb.deviceReady = [this](const std::string& name) {
    emit deviceReady(QString::fromStdString(name));
  };
  cb.preparing = [this](int left) { emit preparingChanged(left); };
  cb.background = [this](std::shared_ptr<const Frame> f) { emit backgroundReady(std::move(f)); };
  worker_ = std::make_unique<RenderWorker>(device.toStdString(), cb, postTo(this));
  sendOutOfCore();  // before the first study: it opens as the preference says
  stateConnection_ = state_.changed.connect([this](unsigned what) {
    if (what != kSlices) requestFrame();  // the slice views' interpolation is not in 3D
  });
  docConnection_ = doc_.changed.connect([this] {
    sawFullFrame_ = false;
    worker_->setVolume(doc_.volume());
    // A 4D series: its other time points go to the device while the view is idle.
    if (doc_.timePoints() > 1) worker_->preload(doc_.series());
    requestFrame();
  });
  // Another time point: the same camera and look on its volume (kept on the device). Played
  // or dragged through, time points come as fast as a drag's cameras: drag frames, the sharp
  // frame once the time point rests.
  timeConnection_ = doc_.timeChanged.connect([this] {
    worker_->setVolume(doc_.volume(), true);
    beginInteraction();
    requestFrame();
  });
  if (!doc_.empty()) worker_->setVolume(doc_.volume());
}

RenderScheduler::~RenderScheduler() {
  state_.changed.disconnect(stateConnection_);
  doc_.changed.disconnect(docConnection_);
  doc_.timeChanged.disconnect(timeConnection_);
  worker_.reset();  // joins the render thread before the callbacks' target goes away
}

void RenderScheduler::setViewSize(QSize size) {
  if (size == viewSize_ || size.isEmpty()) return;
  viewSize_ = size;
  requestFrame();
}

void RenderScheduler::beginInteraction() {
  interacting_ = true;
  settle_.start();
}

void RenderScheduler::endInteraction() {
  settle_.stop();
  interacting_ = false;
  requestFrame();
}

void RenderScheduler::setOverlay(std::shared_ptr<const Volume> overlay, TransferFunction tf) {
  worker_->setOverlay(std::move(overlay), std::move(tf));
  requestFrame();
}

void RenderScheduler::updateSegmentation(SegmentationModel& model) {
  const SegmentationModel::Edits edits = model.takeEdits();
  if (!model.active() || model.segmentation().segments.empty()) {
    worker_->setSegmentation(nullptr);
    sentSegmentation_ = false;
  } else if (edits.whole || !sentSegmentation_) {
    // The render thread copies it for its own (the model goes on changing while it renders);
    // the snapshot hands it over without a copy on the GUI thread (copy on write).
    worker_->setSegmentation(model.snapshot());
    sentSegmentation_ = true;
  } else {
    // After an edit only its box travels (and the list: colours, visibility).
    worker_->updateSegmentation(
        model.segmentation().segments,
        edits.any ? copyLabels(model.segmentation(), edits.lo, edits.hi) : LabelPatch{});
  }
  requestFrame();
}

RenderParams RenderScheduler::fullParams() const {
  return planFrame(state_.params(), state_.quality(), {viewSize_.width(), viewSize_.height()},
                   false, doc_.minSpacingMm());
}

void RenderScheduler::requestExport(QSize size) {
  Quality q = state_.quality();
  q.resolution = {size.width(), size.height()};
  RenderParams p = planFrame(state_.params(), q, q.resolution, false, doc_.minSpacingMm());
  p.width = size.width();  // exactly the size asked for, whatever the preset's image scale
  p.height = size.height();
  worker_->request(p, false, 1);
}

void RenderScheduler::requestPick() {
  if (!doc_.empty())
    worker_->request(pickFrameParams(fullParams(), doc_.minSpacingMm()), false, kPickTag, true);
}

void RenderScheduler::sendOutOfCore() {
  const int mib = state_.quality().gpuBudgetMib;
  if (mib == sentBudgetMib_) return;
  sentBudgetMib_ = mib;
  OutOfCoreSettings o;
  o.budgetBytes = size_t(mib) << 20;
  worker_->setOutOfCore(o);
}

void RenderScheduler::requestFrame() {
  sendOutOfCore();
  if (doc_.empty()) return;
  if (interacting_) settle_.start();  // restart: refine only once the mouse rests
  adaptive_.setTargetFps(state_.quality().dragFps);
  const RenderParams p =
      planFrame(state_.params(), state_.quality(), {viewSize_.width(), viewSize_.height()},
                interacting_, doc_.minSpacingMm(), &adaptive_.setting());
  std::vector<RowBand> bands = viewFrameBands(p, interacting_);
  if (bands.size() > 1)
    worker_->requestBands(p, std::move(bands));
  else
    worker_->request(p, interacting_);
}

std::vector<RenderParams> RenderScheduler::likelyFrames() const {
  const glm::ivec2 size{viewSize_.width(), viewSize_.height()};
  const double h = doc_.minSpacingMm();
  const RenderParams& base = state_.params();
  std::vector<RenderParams> out = {
      planFrame(base, state_.quality(), size, true, h, &adaptive_.setting())};
  for (Mode m : {Mode::Iso, Mode::Dvr, Mode::Mip}) {
    if (m == base.mode) continue;
    RenderParams p = base;
    p.mode = m;
    out.push_back(planFrame(p, state_.quality(), size, false, h));
    out.push_back(planFrame(p, state_.quality(), size, true, h, &adaptive_.setting()));
  }
  return out;
}

void RenderScheduler::requestBackground(std::vector<std::pair<int, RenderParams>> frames) {
  worker_->requestBackground(std::move(frames));
}

void RenderScheduler::onFrame(std::shared_ptr<const Frame> frame) {
  if (frame->tag == kPickTag) {
    emit pickReady(frame);
    return;
  }
  if (frame->tag != 0) {
    emit exportReady(frame);
    return;
  }
  if (frame->coarse) {
    // Issue 38: a new study's preview from its coarse level while the full volume uploads;
    // the status bar says so until the full frame's text replaces it. Not a full frame.
    emit frameReady(frame);
    emit progressChanged(QString::fromUtf8(kCoarsePreviewText));
    return;
  }
  if (frame->bandsDone < frame->bands) {
    emit bandReady(frame);
    return;
  }
  double fps = rate_.frameAt(clock_.nsecsElapsed() * 1e-9, frame->interactive);
  if (frame->interactive) {
    // The setting this frame was rendered with, read back from its size and step.
    const glm::ivec2 r = state_.quality().resolution;
    const int fullWidth = r.x > 0 ? r.x : viewSize_.width();
    adaptive_.record(frame->stats.totalMs,
                     dragSettingOf(frame->params, fullWidth, doc_.minSpacingMm()));
  }
  emit frameReady(frame);
  emit statsChanged(fps, frame->stats.totalMs, frame->interactive);
  const auto& s = frame->stats;
  if (progressive_.onFrame(frame->params, frame->interactive, s.pathSamples, s.pathSeconds) &&
      !interacting_)
    requestFrame();  // the same frame again: one more pass of path samples
  emit progressChanged(QString::fromStdString(progressive_.statusText()));
  if (!frame->interactive && !sawFullFrame_) {
    sawFullFrame_ = true;
    emit firstFullFrame();
    const std::vector<RenderParams> next = likelyFrames();
    emit preparingChanged(int(next.size()));
    worker_->prepare(next);
  }
}

}  // namespace voxray::ui
