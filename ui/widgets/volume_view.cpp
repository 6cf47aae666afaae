#include "volume_view.h"

#include <utility>

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include "camera_control.h"
#include "clip_box_math.h"
#include "light_gizmo.h"
#include "measure_overlay.h"
#include "qt_image.h"
#include "segment_scissors.h"
#include "study_text.h"
#include "surface_pick.h"
#include "tf_drag.h"
#include "volume_overlay.h"

namespace voxray::ui {

namespace {
constexpr double kKeyRotateDeg = 5.0;  // one arrow key press (the seed's step)
constexpr double kWheelZoomPerNotch = 1.1;
constexpr double kLightPickPixels = 14.0;
}  // namespace

VolumeView::VolumeView(RenderStateModel& state, VolumeDocument& doc, CrosshairModel& crosshair,
                       RenderScheduler& scheduler, QWidget* parent)
    : QWidget(parent), state_(state), doc_(doc), crosshair_(crosshair), scheduler_(scheduler) {
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(160, 120);
  setMouseTracking(false);
  auto show = [this](std::shared_ptr<const Frame> f) {
    frame_ = toQImage(f->image);
    frameInteractive_ = f->interactive;
    resolutionNote_ = QString::fromStdString(f->resolutionNote);
    limitsNote_ = QString::fromStdString(f->limitsNote);
    update();
  };
  connect(&scheduler_, &RenderScheduler::frameReady, this, show);
  connect(&scheduler_, &RenderScheduler::bandReady, this, show);  // the sharp frame so far
  connect(&scheduler_, &RenderScheduler::renderError, this, [this] {
    failed_ = true;
    update();
  });
  connect(&scheduler_, &RenderScheduler::pickReady, this,
          [this](std::shared_ptr<const Frame> f) { onPickFrame(*f); });
  stateConnection_ = state_.changed.connect([this](unsigned) { update(); });
  crosshairConnection_ = crosshair_.changed.connect([this] {
    if (state_.overlays().planes) update();
  });
}

VolumeView::~VolumeView() {
  if (measurements_) measurements_->changed.disconnect(measureConnection_);
  state_.changed.disconnect(stateConnection_);
  crosshair_.changed.disconnect(crosshairConnection_);
}

void VolumeView::setMeasurements(MeasurementModel* m) {
  if (measurements_) measurements_->changed.disconnect(measureConnection_);
  measurements_ = m;
  if (m) measureConnection_ = m->changed.connect([this] { update(); });
  update();
}

void VolumeView::onPickFrame(const Frame& f) {
  if (!pickAt_ || doc_.empty()) return;
  const glm::ivec2 size(f.params.width, f.params.height);
  const glm::ivec2 pixel(glm::floor(*pickAt_ * glm::dvec2(size)));
  pickAt_.reset();
  if (std::exchange(pickSegment_, false)) {
    const auto hit = surfaceHitAt(f.hits, size, pixel);
    const uint8_t label =
        hit && segmentation_->active() ? segmentAt(segmentation_->segmentation(), *hit) : 0;
    if (!label) {
      emit pickMissed(hit ? "No segment there: the click hit the volume outside every segment."
                          : QString::fromStdString(pickMissMessage(f.params)));
      return;
    }
    SegmentToolSettings s = segmentTools_->settings();
    s.label = label;
    segmentTools_->set(s);
    return;
  }
  if (!measurements_) return;
  if (auto hit = surfaceHitAt(f.hits, size, pixel))
    measurements_->addPick(*hit);
  else
    emit pickMissed(QString::fromStdString(pickMissMessage(f.params)));
}

QRect VolumeView::imageRect() const {
  RenderParams p = scheduler_.fullParams();
  QSize image(p.width, p.height);
  image.scale(size(), Qt::KeepAspectRatio);
  return QRect(QPoint((width() - image.width()) / 2, (height() - image.height()) / 2), image);
}

std::optional<ViewProjection> VolumeView::projection() const {
  if (doc_.empty()) return std::nullopt;
  QRect r = imageRect();
  return makeViewProjection(*doc_.volume(), scheduler_.fullParams(),
                            glm::dvec2(r.width(), r.height()));
}

glm::dvec2 VolumeView::toImage(QPointF p) const {
  QRect r = imageRect();
  return {p.x() - r.left(), p.y() - r.top()};
}

void VolumeView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), Qt::black);
  QRect r = imageRect();
  if (!frame_.isNull()) painter.drawImage(r, frame_);
  if (const QString n = note(); !n.isEmpty()) {
    painter.setPen(QColor(220, 220, 220));
    painter.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, n);
  }
  auto proj = projection();
  if (!proj) return;
  painter.translate(r.topLeft());
  painter.setRenderHint(QPainter::Antialiasing);
  const Volume& v = *doc_.volume();
  const ViewOverlays& shown = state_.overlays();
  if (shown.planes) drawCrosshairPlanes(painter, v, crosshair_, *proj);
  if (shown.clipHandles) drawClipBox(painter, v, state_.params().clip, *proj, dragFace_);
  if (shown.lightHandle) drawLightHandle(painter, v, state_.params(), *proj, drag_ == Drag::Light);
  if (measurements_)
    drawPickedMeasurements(painter, QRectF(rect()).translated(-r.topLeft()), v, *measurements_,
                           [&](const glm::dvec3& voxel) -> std::optional<QPointF> {
                             auto at = proj->project(voxelToWorldMm(v, voxel));
                             if (!at) return std::nullopt;
                             return QPointF(at->x, at->y);
                           });
  if (lasso_.size() > 1) {
    painter.resetTransform();
    painter.setPen(QPen(QColor(255, 80, 80), 1.5, Qt::DashLine));
    painter.setBrush(QColor(255, 80, 80, 40));
    painter.drawPolygon(lasso_.data(), int(lasso_.size()));
    painter.translate(r.topLeft());
  }
  if (const QString n = frameNote(); !n.isEmpty()) {
    // Top right, over the image: the study text is top left, the orientation marker bottom
    // left.
    const QRect box(QPoint(6, 4), r.size() - QSize(12, 8));
    painter.setPen(QColor(255, 200, 80));
    painter.drawText(box, Qt::AlignRight | Qt::AlignTop | Qt::TextWordWrap, n);
  }
  drawOrientationMarker(painter, proj->g, r.size());
  if (state_.studyText() && !studyTextHidden_)
    drawCornerLines(painter, studyTextLines(v.study), QRect(QPoint(6, 4), r.size()));
}

QString VolumeView::note() const {
  if (doc_.empty() || !frame_.isNull()) return {};
  return failed_ ? QString("No 3D image: the renderer failed (see the message)")
                 : QString("Preparing the 3D renderer…");
}

QString VolumeView::frameNote() const {
  if (resolutionNote_.isEmpty() || limitsNote_.isEmpty()) return resolutionNote_ + limitsNote_;
  return resolutionNote_ + "\n" + limitsNote_;
}

void VolumeView::setStudyTextHidden(bool hidden) {
  studyTextHidden_ = hidden;
  update();
}

void VolumeView::resizeEvent(QResizeEvent*) { scheduler_.setViewSize(size()); }

void VolumeView::mousePressEvent(QMouseEvent* e) {
  dragStart_ = lastPos_ = e->position();
  auto proj = projection();
  drag_ = Drag::None;
  const bool segmentPick =
      segmentTools_ && segmentation_ && segmentTools_->settings().tool != SegmentTool::None;
  if (e->button() == Qt::LeftButton && (e->modifiers() & Qt::ControlModifier) && proj &&
      (measurements_ || segmentPick)) {
    pickSegment_ = segmentPick;
    // A pick, not a drag: the hit arrives with a frame rendered for it (onPickFrame).
    const QRect r = imageRect();
    pickAt_ = toImage(e->position()) / glm::dvec2(std::max(r.width(), 1), std::max(r.height(), 1));
    scheduler_.requestPick();
    return;
  }
  if (e->button() == Qt::LeftButton && proj && segmentTools_ && segmentation_ &&
      segmentTools_->settings().tool == SegmentTool::Scissors &&
      !(e->modifiers() & (Qt::ShiftModifier | Qt::AltModifier))) {
    drag_ = Drag::Scissors;
    lasso_ = {e->position()};
    update();
    return;  // no camera interaction: the frame stays as the lasso is drawn on it
  }
  if (e->button() == Qt::LeftButton && !doc_.empty() &&
      (tfDragMode_ || (e->modifiers() & Qt::AltModifier))) {
    drag_ = Drag::TransferFunction;
    dragStartParams_ = state_.params();
  } else if (e->button() == Qt::LeftButton && proj && !(e->modifiers() & Qt::ShiftModifier)) {
    const Volume& v = *doc_.volume();
    glm::dvec2 at = toImage(e->position());
    auto light = proj->project(lightHandleWorld(v, state_.params()));
    const ViewOverlays& shown = state_.overlays();
    if (shown.lightHandle && light && glm::distance(*light, at) <= kLightPickPixels) {
      drag_ = Drag::Light;
    } else if (auto face = shown.clipHandles ? pickClipFace(v, state_.params().clip, *proj, at)
                                             : std::nullopt) {
      drag_ = Drag::ClipFace;
      dragFace_ = *face;
      dragStartBox_ = state_.params().clip;
    }
  }
  if (drag_ == Drag::None) {
    if (e->button() == Qt::MiddleButton ||
        (e->button() == Qt::LeftButton && (e->modifiers() & Qt::ShiftModifier)))
      drag_ = Drag::Pan;
    else if (e->button() == Qt::RightButton)
      drag_ = Drag::Zoom;
    else if (e->button() == Qt::LeftButton)
      drag_ = Drag::Rotate;
  }
  if (drag_ != Drag::None) scheduler_.beginInteraction();
  update();
}

void VolumeView::mouseMoveEvent(QMouseEvent* e) {
  if (drag_ == Drag::None || doc_.empty()) return;
  if (drag_ == Drag::Scissors) {
    lasso_.push_back(e->position());
    update();
    return;
  }
  QPointF d = e->position() - lastPos_;
  lastPos_ = e->position();
  scheduler_.beginInteraction();
  const Volume& v = *doc_.volume();
  switch (drag_) {
    case Drag::Rotate:
      state_.update(kCamera, [&](RenderParams& p) { orbit(p.camera, d.x(), d.y()); });
      break;
    case Drag::Zoom:
      state_.update(kCamera, [&](RenderParams& p) { zoomBy(p.camera, std::pow(1.01, -d.y())); });
      break;
    case Drag::Pan: {
      double mm = projection() ? projection()->mmPerPixel() : 1.0;
      state_.update(kCamera, [&](RenderParams& p) { panBy(p.camera, d.x(), d.y(), mm); });
      break;
    }
    case Drag::ClipFace: {
      QPointF total = e->position() - dragStart_;
      ClipBox box = dragClipFace(v, dragStartBox_, *projection(), dragFace_,
                                 glm::dvec2(total.x(), total.y()));
      state_.update(kClip, [&](RenderParams& p) { p.clip = box; });
      break;
    }
    case Drag::Light: {
      LightParams l = lightFromScreen(v, state_.params(), *projection(), toImage(e->position()));
      state_.update(kLight, [&](RenderParams& p) { p.light = l; });
      break;
    }
    case Drag::TransferFunction: {
      // A drag across the view's height moves the table over the volume's value range.
      QPointF total = e->position() - dragStart_;
      ValueRange r = storedRange(v);
      double span = std::max(100.0, std::abs(v.toPhysical(r.max) - v.toPhysical(r.min)));
      glm::dvec2 moved(total.x() / std::max(1, width()), -total.y() / std::max(1, height()));
      RenderParams shaped = dragTransferFunction(dragStartParams_, moved, span,
                                                 e->modifiers().testFlag(Qt::ControlModifier));
      state_.update(kAppearance, [&](RenderParams& p) {
        p.preset = shaped.preset;
        p.presetShiftHu = shaped.presetShiftHu;
        p.transferFunction = shaped.transferFunction;
        p.isoLo = shaped.isoLo;
        p.isoHi = shaped.isoHi;
        p.windowWidth = shaped.windowWidth;
        p.windowLevel = shaped.windowLevel;
      });
      break;
    }
    case Drag::None:
      break;
  }
}

void VolumeView::mouseReleaseEvent(QMouseEvent*) {
  if (drag_ == Drag::None) return;
  if (drag_ == Drag::Scissors) {
    drag_ = Drag::None;
    std::vector<glm::dvec2> polygon;
    for (const QPointF& p : std::exchange(lasso_, {})) polygon.push_back(toImage(p));
    auto proj = projection();
    if (proj && polygon.size() >= 3 && !doc_.empty()) {
      try {
        const SegmentToolSettings& s = segmentTools_->settings();
        applyScissors(*segmentation_, *doc_.volume(), *proj, polygon, s.label,
                      s.scissorsKeep ? ScissorsMode::Keep : ScissorsMode::Remove);
      } catch (const std::exception& e) {
        emit segmentToolFailed(QString::fromStdString(e.what()));
      }
    }
    update();
    return;
  }
  drag_ = Drag::None;
  dragFace_ = -1;
  scheduler_.endInteraction();
  update();
}

void VolumeView::mouseDoubleClickEvent(QMouseEvent*) { emit doubleClicked(); }

void VolumeView::wheelEvent(QWheelEvent* e) {
  double notches = e->angleDelta().y() / 120.0;
  scheduler_.beginInteraction();
  state_.update(kCamera,
                [&](RenderParams& p) { zoomBy(p.camera, std::pow(kWheelZoomPerNotch, notches)); });
}

void VolumeView::keyPressEvent(QKeyEvent* e) {
  double dAz = 0, dEl = 0;
  switch (e->key()) {
    case Qt::Key_Left:
      dAz = -kKeyRotateDeg;
      break;
    case Qt::Key_Right:
      dAz = kKeyRotateDeg;
      break;
    case Qt::Key_Up:
      dEl = kKeyRotateDeg;
      break;
    case Qt::Key_Down:
      dEl = -kKeyRotateDeg;
      break;
    case Qt::Key_R:
      state_.update(kCamera, [](RenderParams& p) { resetCamera(p.camera); });
      return;
    default:
      QWidget::keyPressEvent(e);
      return;
  }
  // Same sense as dragging: the key turns the volume the way the arrow points.
  state_.update(kCamera, [&](RenderParams& p) { orbit(p.camera, dAz, -dEl, 1.0); });
}

}  // namespace voxray::ui
