#include "slice_view.h"

#include <cmath>
#include <functional>

#include <QGuiApplication>
#include <QLineEdit>
#include <QMouseEvent>
#include <QPainter>
#include <QStyleHints>
#include <QWheelEvent>

#include "annotation_overlay.h"
#include "gui_post.h"
#include "measure_overlay.h"
#include "qt_image.h"
#include "segment_overlay.h"
#include "slice_clip.h"
#include "slice_image.h"
#include "slice_overlay.h"
#include "status_text.h"
#include "study_text.h"
#include "voxray/engine/measure.h"

namespace voxray::ui {

namespace {
constexpr double kEdgePickPixels = 6.0;
// Shorter drags are clicks: an arrow needs a direction a reader can see.
constexpr double kMinArrowPixels = 4.0;

// The Text tool's line edit: Esc drops the text (a plain QLineEdit ignores it).
class AnnotationTextEdit : public QLineEdit {
 public:
  using QLineEdit::QLineEdit;
  std::function<void()> onEscape;

 protected:
  void keyPressEvent(QKeyEvent* e) override {
    if (e->key() == Qt::Key_Escape && onEscape)
      onEscape();
    else
      QLineEdit::keyPressEvent(e);
  }
};
}  // namespace

SliceView::SliceView(Orientation o, VolumeDocument& doc, CrosshairModel& crosshair,
                     WindowLevelModel& wl, RenderStateModel& state, QWidget* parent)
    : QWidget(parent),
      orientation_(o),
      doc_(doc),
      crosshair_(crosshair),
      wl_(wl),
      state_(state),
      slabs_([this](Image image) { slabArrived(std::move(image)); }, postTo(this)) {
  setFocusPolicy(Qt::StrongFocus);
  setMouseTracking(true);
  setMinimumSize(120, 120);
  docConnection_ = doc_.changed.connect([this] {
    zoom_ = 1.0;
    pan_ = {};
    shown_.reset();
    rebuild();
  });
  // Another time point: the same plane, zoom and pan on its volume.
  timeConnection_ = doc_.timeChanged.connect([this] {
    shown_.reset();
    wanted_.reset();  // a slab of the last time point still rendering is stale
    rebuild();
  });
  crossConnection_ = crosshair_.changed.connect([this] { rebuild(); });
  wlConnection_ = wl_.changed.connect([this] { rebuild(); });
  stateConnection_ = state_.changed.connect([this](unsigned what) {
    if (what & kSlices)
      rebuild();
    else if (what & kClip)
      update();
  });
  rebuild();
}

SliceView::~SliceView() {
  if (fusion_) fusion_->changed.disconnect(fusionConnection_);
  if (measurements_) measurements_->changed.disconnect(measureConnection_);
  if (annotationModel_) annotationModel_->changed.disconnect(annotationConnection_);
  if (segmentation_) segmentation_->changed.disconnect(segConnection_);
  if (segmentTools_) segmentTools_->changed.disconnect(toolConnection_);
  doc_.changed.disconnect(docConnection_);
  doc_.timeChanged.disconnect(timeConnection_);
  crosshair_.changed.disconnect(crossConnection_);
  wl_.changed.disconnect(wlConnection_);
  state_.changed.disconnect(stateConnection_);
}

void SliceView::setAnnotations(bool on) {
  annotations_ = on;
  update();
}

void SliceView::setStudyTextHidden(bool hidden) {
  studyTextHidden_ = hidden;
  update();
}

void SliceView::setMeasurements(MeasurementModel* m) {
  if (measurements_) measurements_->changed.disconnect(measureConnection_);
  measurements_ = m;
  if (m) measureConnection_ = m->changed.connect([this] { update(); });
  update();
}

void SliceView::setAnnotationModel(AnnotationModel* a) {
  if (annotationModel_) annotationModel_->changed.disconnect(annotationConnection_);
  annotationModel_ = a;
  if (a) annotationConnection_ = a->changed.connect([this] { update(); });
  update();
}

void SliceView::setExporting(bool on) {
  exporting_ = on;
  update();
}

QImage SliceView::cleanImage(bool layers) const {
  if (image_.isNull()) return {};
  QImage out = image_.convertToFormat(QImage::Format_RGB32);
  if (layers) {
    // The overlays have the plane's size (the slice image's): pixel onto pixel.
    QPainter p(&out);
    for (const QImage* layer : {&fusionOverlay_, &segmentOverlay_})
      if (!layer->isNull()) p.drawImage(out.rect(), *layer);
  }
  return out;
}

void SliceView::setSegmentation(SegmentationModel* model, SegmentToolModel* tools) {
  if (segmentation_) segmentation_->changed.disconnect(segConnection_);
  if (segmentTools_) segmentTools_->changed.disconnect(toolConnection_);
  segmentation_ = model;
  segmentTools_ = tools;
  if (model)
    segConnection_ = model->changed.connect([this] {
      refreshSegmentOverlay();
      update();
    });
  if (tools)
    toolConnection_ = tools->changed.connect([this] {
      refreshSegmentOverlay();
      update();
    });
  refreshSegmentOverlay();
  update();
}

void SliceView::setFusion(FusionModel* fusion) {
  if (fusion_) fusion_->changed.disconnect(fusionConnection_);
  fusion_ = fusion;
  fusedPlane_.reset();
  if (fusion)
    fusionConnection_ = fusion->changed.connect([this] {
      refreshFusion(true);
      update();
    });
  refreshFusion();
  update();
}

void SliceView::refreshFusion(bool force) {
  if (!fusion_ || !fusion_->active() || !shown_ || doc_.empty()) {
    fusionOverlay_ = {};
    fusedPlane_.reset();
    return;
  }
  // A crosshair move elsewhere leaves this view's plane as it was: keep its overlay.
  const PlaneGrid& g = shown_->plane;
  if (!force && fusedPlane_ && fusedPlane_->originMm == g.originMm && fusedPlane_->uDir == g.uDir &&
      fusedPlane_->vDir == g.vDir && fusedPlane_->spacingMm == g.spacingMm &&
      fusedPlane_->size == g.size)
    return;
  fusedPlane_ = g;
  fusionOverlay_ = {};
  try {
    fusionOverlay_ = toQImage(fusionImage(*fusion_->overlay(), shown_->plane, fusion_->settings()));
  } catch (const std::exception&) {  // settings are checked when set: nothing to draw
  }
}

void SliceView::setZoom(double zoom) {
  zoom = std::clamp(zoom, 0.25, 32.0);
  if (zoom == zoom_) return;
  zoom_ = zoom;
  update();
  emit zoomChanged(zoom_);
}

void SliceView::refreshSegmentOverlay() {
  segmentOverlay_ = {};
  previewOverlay_ = {};
  if (!shown_ || doc_.empty()) return;
  const Volume& v = *doc_.volume();
  const PlaneGrid& plane = shown_->plane;
  const Segmentation* seg = nullptr;
  if (segmentation_ && segmentation_->active() &&
      sameGrid(segmentation_->segmentation().grid, gridOf(v)))
    seg = &segmentation_->segmentation();
  if (seg && !seg->segments.empty()) segmentOverlay_ = toQImage(segmentOverlay(*seg, plane));
  if (segmentTools_ && segmentTools_->settings().tool == SegmentTool::Threshold) {
    // The preview in the chosen segment's colour (a yellow without one).
    glm::vec3 colour(1.0f, 0.85f, 0.1f);
    if (seg)
      if (const Segment* s = seg->find(segmentTools_->settings().label)) colour = s->colour;
    try {
      previewOverlay_ =
          toQImage(thresholdOverlay(v, plane, segmentTools_->settings().range, colour));
    } catch (const std::exception&) {  // a range with lo > hi previews nothing
    }
  }
}

size_t SliceView::thresholdPreviewVoxels() const {
  if (doc_.empty() || !segmentTools_) return 0;
  try {
    return previewCount(*doc_.volume(), axes_.nAxis, crosshair_.sliceOf(axes_),
                        segmentTools_->settings().range);
  } catch (const std::exception&) {
    return 0;
  }
}

glm::dvec3 SliceView::toolVoxel(QPointF widget) const {
  const glm::dvec2 s = toSlice(widget);
  return crosshair_.viewToVoxel(axes_, s.x, s.y);
}

bool SliceView::pressSegmentTool(QPointF at) {
  if (!segmentation_ || !segmentTools_ || doc_.empty()) return false;
  const SegmentTool tool = segmentTools_->settings().tool;
  if (tool != SegmentTool::Paint && tool != SegmentTool::Erase && tool != SegmentTool::Seed)
    return false;
  if (!sliceRect().contains(at)) return false;
  try {
    if (tool == SegmentTool::Seed) {
      seedClick(*segmentation_, *doc_.volume(), segmentTools_->settings(),
                nearestVoxel(toolVoxel(at)));
      drag_ = Drag::None;
    } else {
      segmentation_->beginStroke();
      drag_ = Drag::Brush;
      brushAt(at);
    }
  } catch (const std::exception& e) {
    emit segmentToolFailed(QString::fromStdString(e.what()));
  }
  return true;
}

void SliceView::brushAt(QPointF at) {
  if (!sliceRect().contains(at)) return;
  SegmentToolSettings s = segmentTools_->settings();
  // A turned plane is no index slice: its brush is the ball (a disc needs an index slice).
  if (!isIdentity(crosshair_.rotation(orientation_))) s.sphere = true;
  const glm::dvec3 voxel = toolVoxel(at);
  const glm::ivec3& dims = doc_.volume()->dims;
  if (glm::any(glm::lessThan(voxel, glm::dvec3(-0.5))) ||
      glm::any(glm::greaterThanEqual(voxel, glm::dvec3(dims) - 0.5)))
    return;
  brushDab(*segmentation_, s, axes_.nAxis, voxel);
}

QPointF SliceView::voxelToWidget(const glm::dvec3& voxel) const {
  const glm::dvec2 s = voxelToSlice(axes_, doc_.volume()->dims, voxel);
  return toWidget(s.x, s.y);
}

glm::dvec3 SliceView::widgetToVoxel(QPointF widget) const {
  const glm::dvec2 s = toSlice(widget);
  const glm::ivec3& dims = doc_.volume()->dims;
  return clampToVolume(sliceToVoxel(axes_, dims, s.x, s.y, crosshair_.sliceOf(axes_)), dims);
}

bool SliceView::measurable() const {
  return isIdentity(crosshair_.rotation(orientation_)) &&
         crosshair_.slab(orientation_).thicknessMm == 0;
}

QPointF SliceView::mmToWidget(const glm::dvec3& patientMm) const {
  return voxelToWidget(patientToVoxel(*doc_.volume(), patientMm));
}

glm::dvec3 SliceView::widgetToMm(QPointF widget) const {
  return voxelToPatient(*doc_.volume(), widgetToVoxel(widget));
}

bool SliceView::pressAnnotation(QPointF at) {
  if (!annotationModel_ || !measurements_ || !measurable()) return false;
  const MeasureTool tool = measurements_->tool();
  if (tool == MeasureTool::Arrow) {
    arrowHeadMm_ = widgetToMm(at);
    arrowTail_ = at;
    drag_ = Drag::Arrow;
    return true;
  }
  if (tool != MeasureTool::Text) return false;
  if (textEdit_) textEdit_->deleteLater();  // a second click elsewhere: start over there
  auto* edit = new AnnotationTextEdit(this);
  edit->setObjectName("annotationTextEdit");
  edit->setPlaceholderText("Text, Return to add");
  edit->setToolTip("Return adds the text here; Esc or an empty text adds nothing");
  edit->move(at.toPoint());
  edit->resize(std::min(240, std::max(80, width() - int(at.x()))), edit->sizeHint().height());
  edit->show();
  edit->setFocus();
  textEdit_ = edit;
  // Both Return and focus leaving end the edit; the QPointer keeps it to one add.
  QObject::connect(edit, &QLineEdit::editingFinished, this, [this, edit, at] {
    if (textEdit_ != edit) return;
    textEdit_ = nullptr;
    edit->deleteLater();
    finishText(at, edit->text());
  });
  edit->onEscape = [this, edit] {
    if (textEdit_ != edit) return;
    textEdit_ = nullptr;
    edit->deleteLater();
    setFocus();
  };
  return true;
}

void SliceView::finishText(QPointF at, const QString& text) {
  const QString t = text.trimmed();
  if (t.isEmpty() || !annotationModel_ || doc_.empty() || !measurable()) return;
  annotationModel_->addText(t.toStdString(), widgetToMm(at), sliceNormal(*doc_.volume(), axes_));
  setFocus();
}

bool SliceView::pressMeasure(QPointF at) {
  if (!measurements_ || !measurable()) return false;
  const int slice = crosshair_.sliceOf(axes_);
  // A handle under the cursor wins in any mode: the nearest one within reach.
  double best = kHandlePickPixels;
  dragId_ = 0;
  for (const Measurement& m : measurements_->items()) {
    if (!shownOnSlice(m, axes_, slice)) continue;
    for (size_t i = 0; i < m.points.size(); ++i) {
      const QPointF d = voxelToWidget(m.points[i]) - at;
      const double dist = std::hypot(d.x(), d.y());
      if (dist <= best) {
        best = dist;
        dragId_ = m.id;
        dragIndex_ = int(i);
      }
    }
  }
  if (dragId_) {
    measurements_->select(dragId_);
    return true;
  }
  const glm::dvec3 p = widgetToVoxel(at);
  if (angleToFinish_ && measurements_->find(angleToFinish_)) {
    dragId_ = std::exchange(angleToFinish_, 0);
    dragIndex_ = 2;
    measurements_->movePoint(dragId_, dragIndex_, p);
    return true;
  }
  angleToFinish_ = 0;
  const MeasureTool tool = measurements_->tool();
  if (tool == MeasureTool::None || tool == MeasureTool::Text || tool == MeasureTool::Arrow)
    return false;
  const MeasureKind kind = tool == MeasureTool::Distance ? MeasureKind::Distance
                           : tool == MeasureTool::Angle  ? MeasureKind::Angle
                           : tool == MeasureTool::Rect   ? MeasureKind::Rect
                                                         : MeasureKind::Ellipse;
  dragId_ =
      measurements_->add(kind, std::vector<glm::dvec3>(size_t(pointCount(kind)), p), axes_.nAxis);
  dragIndex_ = 1;  // the far end, the vertex, or the opposite corner follows the drag
  if (kind == MeasureKind::Angle) angleToFinish_ = dragId_;
  return true;
}

void SliceView::rebuild() {
  if (doc_.empty()) {
    image_ = {};
    shown_.reset();
    wanted_.reset();
    slabs_.drop();
  } else {
    const Volume& v = *doc_.volume();
    axes_ = sliceAxes(v.direction, orientation_);
    // A crosshair move elsewhere often leaves this view's slice as it was: keep its image
    // (resampling a large slice takes tens of milliseconds).
    const Shown now{viewPlane(v, axes_, crosshair_.centre(), crosshair_.rotation(orientation_)),
                    crosshair_.slab(orientation_), wl_.value(), state_.sliceInterp()};
    if (shown_ && now.sameAs(*shown_)) {
      wanted_.reset();  // back to what is shown: a slab still rendering is stale
      slabs_.drop();
    } else if (now.slab.thicknessMm > 0) {
      // A slab takes up to a second: render it in the background, newest request wins.
      if (!wanted_ || !now.sameAs(*wanted_)) {
        wanted_ = now;
        slabs_.request({doc_.volume(), now.plane, now.wl, now.interp, now.slab});
      }
      // Meanwhile the last slab image stays; with none (a slab just switched on, a new
      // volume, another size) the thin slice stands in.
      if (!shown_ || shown_->slab.thicknessMm == 0 || shown_->plane.size != now.plane.size) {
        Shown thin = now;
        thin.slab = {};
        if (!shown_ || !thin.sameAs(*shown_)) {
          image_ = toQImage(renderPlane(v, thin.plane, thin.wl, thin.interp));
          shown_ = thin;
        }
      }
    } else {
      wanted_.reset();
      slabs_.drop();
      image_ = toQImage(renderPlane(v, now.plane, now.wl, now.interp, now.slab));
      shown_ = now;
    }
  }
  refreshSegmentOverlay();
  refreshFusion();
  update();
}

void SliceView::slabArrived(Image image) {
  if (!wanted_) return;
  image_ = toQImage(image);
  shown_ = std::exchange(wanted_, std::nullopt);
  refreshFusion();
  update();
  emit slabShown();
}

QRectF SliceView::sliceRect() const {
  if (doc_.empty() || image_.isNull()) return {};
  const Volume& v = *doc_.volume();
  // The slice's size in millimetres (the image has its aspect, renderSlice).
  double wMm = v.dims[axes_.uAxis] * v.spacingMm[axes_.uAxis];
  double hMm = v.dims[axes_.vAxis] * v.spacingMm[axes_.vAxis];
  double scale = std::min(width() / wMm, height() / hMm) * zoom_;
  QSizeF s(wMm * scale, hMm * scale);
  QPointF topLeft((width() - s.width()) / 2 + pan_.x(), (height() - s.height()) / 2 + pan_.y());
  return {topLeft, s};
}

QPointF SliceView::toWidget(double u, double v) const {
  QRectF r = sliceRect();
  if (r.isEmpty()) return {};
  const glm::ivec3& dims = doc_.volume()->dims;
  return {r.left() + u / dims[axes_.uAxis] * r.width(),
          r.top() + v / dims[axes_.vAxis] * r.height()};
}

glm::dvec2 SliceView::toSlice(QPointF p) const {
  QRectF r = sliceRect();
  if (r.isEmpty()) return {0, 0};
  const glm::ivec3& dims = doc_.volume()->dims;
  return {(p.x() - r.left()) / r.width() * dims[axes_.uAxis],
          (p.y() - r.top()) / r.height() * dims[axes_.vAxis]};
}

int SliceView::pickClipEdge(QPointF p) const {
  if (doc_.empty() || state_.params().clip.isFull()) return -1;  // no box drawn: no handles
  int best = -1;
  double bestDist = kEdgePickPixels;
  for (const auto& e : sliceClipEdges(axes_, doc_.volume()->dims, state_.params().clip)) {
    QPointF at = e.vertical ? toWidget(e.position, 0) : toWidget(0, e.position);
    double d = e.vertical ? std::abs(at.x() - p.x()) : std::abs(at.y() - p.y());
    if (d <= bestDist) {
      bestDist = d;
      best = e.face;
    }
  }
  return best;
}

std::array<glm::dvec2, 2> SliceView::crosshairTraces() const {
  if (!crosshair_.rotated()) return SliceOverlay{}.traces;
  // The other planes' traces: the one whose normal lies nearer this view's screen x is the
  // upright line (drawn in the colour of that axis while nothing is turned).
  const PlaneFrame mine = crosshair_.frame(axes_);
  std::array<glm::dvec3, 2> normals;
  size_t n = 0;
  for (Orientation o : {Orientation::Axial, Orientation::Coronal, Orientation::Sagittal})
    if (o != orientation_)
      normals[n++] = crosshair_.frame(sliceAxes(crosshair_.direction(), o)).normal;
  if (std::abs(glm::dot(normals[1], mine.right)) > std::abs(glm::dot(normals[0], mine.right)))
    std::swap(normals[0], normals[1]);
  return {traceOnScreen(mine, normals[0]), traceOnScreen(mine, normals[1])};
}

std::array<QPointF, 4> SliceView::rotationHandles() const {
  if (doc_.empty()) return {};
  const glm::dvec2 c = voxelToSlice(axes_, doc_.volume()->dims, crosshair_.centre());
  return ui::rotationHandles(font(), rect(), toWidget(c.x, c.y), crosshairTraces());
}

bool SliceView::onRotationHandle(QPointF p) const {
  const QRectF shown = crosshairBounds(font(), rect());  // where the overlay draws them
  for (const QPointF& h : rotationHandles())
    if (shown.contains(h) && QLineF(h, p).length() <= kRotateHandleRadius + 3.0) return true;
  return false;
}

void SliceView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), Qt::black);
  if (image_.isNull()) return;
  p.drawImage(sliceRect(), image_);
  if (!fusionOverlay_.isNull()) p.drawImage(sliceRect(), fusionOverlay_);
  // Nearest-neighbour scaling (no smooth transform): each voxel a crisp block of colour.
  if (!segmentOverlay_.isNull()) p.drawImage(sliceRect(), segmentOverlay_);
  if (!previewOverlay_.isNull()) p.drawImage(sliceRect(), previewOverlay_);
  paintOverlay(p);
  if (segmentTools_ && rect().contains(hover_.toPoint()) &&
      (segmentTools_->settings().tool == SegmentTool::Paint ||
       segmentTools_->settings().tool == SegmentTool::Erase)) {
    // The brush's reach: its radius in millimetres at the view's scale.
    const Volume& v = *doc_.volume();
    const double mmPerPixel = v.dims[axes_.uAxis] * v.spacingMm[axes_.uAxis] / sliceRect().width();
    const double r = segmentTools_->settings().radiusMm / mmPerPixel;
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(QColor(255, 255, 255, 200), 1.0));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(hover_, r, r);
  }
}

void SliceView::paintOverlay(QPainter& p) {
  const Volume& v = *doc_.volume();
  SliceOverlay o;
  o.axes = axes_;
  const bool oblique = !isIdentity(crosshair_.rotation(orientation_));
  if (oblique) o.axes.labels = frameLabels(crosshair_.frame(axes_));
  o.crosshair = voxelToSlice(axes_, v.dims, crosshair_.centre());
  o.traces = crosshairTraces();
  o.rotateHandles = true;
  const Slab& slab = crosshair_.slab(orientation_);
  o.planeNote = oblique ? "oblique" : "";
  if (slab.thicknessMm > 0) {
    const std::string mode = QString(toString(slab.mode)).toUpper().toStdString();
    o.planeNote += (o.planeNote.empty() ? "" : ", ") + mode + " " +
                   QString::number(slab.thicknessMm).toStdString() + " mm";
  }
  if (doc_.timePoints() > 1)  // a 4D series: which time point this is, 1-based as read
    o.planeNote += (o.planeNote.empty() ? "" : ", ") + std::string("time ") +
                   std::to_string(doc_.timePoint() + 1) + "/" + std::to_string(doc_.timePoints());
  o.clipEdges = sliceClipEdges(axes_, v.dims, state_.params().clip);
  o.showClip = !state_.params().clip.isFull() || dragFace_ >= 0;
  o.clipActive = sliceInsideClip(axes_, v.dims, state_.params().clip, crosshair_.sliceOf(axes_));
  o.slice = crosshair_.sliceOf(axes_);
  o.sliceCount = v.dims[axes_.nAxis];
  o.wl = wl_.value();
  o.wlSource = wl_.source();
  if (state_.studyText() && !studyTextHidden_) o.studyLines = studyTextLines(v.study);
  o.mmPerWidgetPixel = v.dims[axes_.uAxis] * v.spacingMm[axes_.uAxis] / sliceRect().width();
  if (annotations_ && rect().contains(hover_.toPoint())) {
    glm::dvec2 s = toSlice(hover_);
    glm::dvec3 voxel = crosshair_.viewToVoxel(axes_, s.x, s.y);
    o.hasCursor = true;
    // Read as the view samples: the probe follows the slice interpolation setting.
    o.cursorText = formatCursorProbe(probeAt(v, voxel, state_.sliceInterp()));
    if (fusion_ && fusion_->active())
      o.cursorText += "  " + fusionProbeText(*fusion_->overlay(), voxelToPatientMm(v, voxel));
  }
  cursorReadout_ = QString::fromStdString(o.cursorText);
  drawSliceOverlay(p, o, rect(), [this](double u, double vv) { return toWidget(u, vv); });
  if (measurements_ && measurable() && (!exporting_ || measurements_->showInExports()))
    drawSliceMeasurements(p, rect(), v, *measurements_, axes_, o.slice,
                          [this](const glm::dvec3& voxel) { return voxelToWidget(voxel); });
  // Annotations follow the measurements' choice for exports: both are what the reader marked.
  const bool exportShows = !exporting_ || (measurements_ && measurements_->showInExports());
  if (annotationModel_ && measurable() && exportShows)
    drawSliceAnnotations(p, rect(), v, *annotationModel_, axes_, o.slice,
                         [this](const glm::dvec3& mm) { return mmToWidget(mm); });
  if (drag_ == Drag::Arrow) drawArrow(p, mmToWidget(arrowHeadMm_), arrowTail_, kAnnotationColor);
}

void SliceView::mousePressEvent(QMouseEvent* e) {
  lastPos_ = dragStart_ = e->position();
  drag_ = Drag::None;
  const std::optional<ClickChain> chain = std::exchange(clickChain_, std::nullopt);
  if (doc_.empty()) return;
  const bool plain = !(e->modifiers() & (Qt::ControlModifier | Qt::ShiftModifier));
  if (e->button() == Qt::LeftButton && plain &&
      (pressSegmentTool(e->position()) || pressAnnotation(e->position()))) {
    return;  // a segment tool, else the annotation tool, took the press
  } else if (e->button() == Qt::LeftButton && pressMeasure(e->position())) {
    drag_ = Drag::Handle;
  } else if (e->button() == Qt::LeftButton) {
    dragFace_ = pickClipEdge(e->position());
    drag_ = dragFace_ >= 0                    ? Drag::ClipEdge
            : onRotationHandle(e->position()) ? Drag::Rotate
                                              : Drag::Crosshair;
    if (drag_ == Drag::Crosshair) {
      // Where the crosshair was before the first press of presses that may make a
      // double-click (Qt 6 sends both presses before the double-click event).
      const auto within = ulong(QGuiApplication::styleHints()->mouseDoubleClickInterval());
      clickChain_ = chain && e->timestamp() - chain->at <= within
                        ? ClickChain{chain->before, e->timestamp()}
                        : ClickChain{crosshair_.centre(), e->timestamp()};
      glm::dvec2 s = toSlice(e->position());
      crosshair_.clickInView(axes_, s.x, s.y);
    }
  } else if (e->button() == Qt::RightButton) {
    drag_ = Drag::WindowLevel;
    dragStartWl_ = wl_.value();
  } else if (e->button() == Qt::MiddleButton) {
    drag_ = Drag::Pan;
  }
}

void SliceView::mouseMoveEvent(QMouseEvent* e) {
  hover_ = e->position();
  QPointF d = e->position() - lastPos_;
  lastPos_ = e->position();
  glm::dvec2 s = toSlice(e->position());
  switch (drag_) {
    case Drag::Crosshair:
      crosshair_.clickInView(axes_, s.x, s.y);
      break;
    case Drag::ClipEdge: {
      const auto& edges = sliceClipEdges(axes_, doc_.volume()->dims, state_.params().clip);
      bool vertical = false;
      for (const auto& edge : edges)
        if (edge.face == dragFace_) vertical = edge.vertical;
      emit clipDragged();  // before the change, so that its frame is already a drag frame
      state_.update(kClip, [&](RenderParams& p) {
        dragSliceClipEdge(p.clip, axes_, doc_.volume()->dims, dragFace_, vertical ? s.x : s.y);
      });
      break;
    }
    case Drag::WindowLevel: {
      QPointF total = e->position() - dragStart_;
      wl_.set(dragWindowLevel(dragStartWl_, total.x(), total.y()));
      break;
    }
    case Drag::Pan:
      pan_ += d;
      break;
    case Drag::Handle:
      measurements_->movePoint(dragId_, dragIndex_, widgetToVoxel(e->position()));
      break;
    case Drag::Rotate: {
      // The angle swept about the crosshair, clockwise positive on this y-down screen; the
      // screen shows millimetres square, so it is the angle in the patient too.
      const glm::dvec2 c = voxelToSlice(axes_, doc_.volume()->dims, crosshair_.centre());
      const QPointF at = toWidget(c.x, c.y);
      const QPointF a = e->position() - d - at, b = e->position() - at;
      crosshair_.rotateInView(
          axes_, std::atan2(a.x() * b.y() - a.y() * b.x(), a.x() * b.x() + a.y() * b.y()));
      break;
    }
    case Drag::Arrow:
      arrowTail_ = e->position();
      break;
    case Drag::Brush:
      try {
        brushAt(e->position());
      } catch (const std::exception& ex) {
        emit segmentToolFailed(QString::fromStdString(ex.what()));
      }
      break;
    case Drag::None:
      break;
  }
  update();
}

void SliceView::mouseReleaseEvent(QMouseEvent* e) {
  if (drag_ == Drag::Arrow && !doc_.empty()) {
    // A click without a drag is no arrow: its direction would be nothing.
    if (QLineF(e->position(), mmToWidget(arrowHeadMm_)).length() >= kMinArrowPixels)
      annotationModel_->addArrow(arrowHeadMm_, widgetToMm(e->position()),
                                 sliceNormal(*doc_.volume(), axes_));
  }
  if (drag_ == Drag::ClipEdge) emit clipDragEnded();
  if (drag_ == Drag::Brush) segmentation_->endStroke();
  drag_ = Drag::None;
  dragFace_ = -1;
  update();
}

void SliceView::mouseDoubleClickEvent(QMouseEvent*) {
  // A double-click maximises or restores the view only: the crosshair goes back to where
  // it was before the double-click's presses moved it.
  if (clickChain_) {
    std::array<glm::dmat3, 3> rotations;
    for (size_t o = 0; o < rotations.size(); ++o)
      rotations[o] = crosshair_.rotation(Orientation(o));
    crosshair_.setPlanes(clickChain_->before, rotations);
    clickChain_.reset();
  }
  emit doubleClicked();
}

void SliceView::wheelEvent(QWheelEvent* e) {
  int notches = e->angleDelta().y() / 120;
  if (e->modifiers() & Qt::ControlModifier) {
    setZoom(zoom_ * std::pow(1.15, notches));
  } else {
    crosshair_.scrollView(axes_, notches);
  }
}

void SliceView::keyPressEvent(QKeyEvent* e) {
  switch (e->key()) {
    case Qt::Key_Up:
    case Qt::Key_Right:
      crosshair_.scrollView(axes_, 1);
      break;
    case Qt::Key_Down:
    case Qt::Key_Left:
      crosshair_.scrollView(axes_, -1);
      break;
    case Qt::Key_PageUp:
      crosshair_.scrollView(axes_, 10);
      break;
    case Qt::Key_PageDown:
      crosshair_.scrollView(axes_, -10);
      break;
    case Qt::Key_Delete:
    case Qt::Key_Backspace:
      if (annotationModel_ && annotationModel_->selected())
        annotationModel_->remove(annotationModel_->selected());
      else if (measurements_ && measurements_->selected())
        measurements_->remove(measurements_->selected());
      break;
    case Qt::Key_Escape:
      angleToFinish_ = 0;
      if (measurements_) measurements_->setTool(MeasureTool::None);
      break;
    default:
      QWidget::keyPressEvent(e);
  }
}

void SliceView::leaveEvent(QEvent*) {
  hover_ = {-1, -1};
  update();
}

}  // namespace voxray::ui
