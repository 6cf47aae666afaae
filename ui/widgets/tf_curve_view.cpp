#include "tf_curve_view.h"

#include <algorithm>
#include <cmath>

#include <QColorDialog>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include "coupling.h"

namespace voxray::ui {

namespace {

constexpr double kCurveMargin = 8.0;
constexpr double kBarHeight = 18.0;
constexpr double kAxisHeight = 16.0;                            // the HU labels' strip
constexpr double kCurveMinSpanHu = 1.0, kCurveMaxSpanHu = 1e6;  // how far the axis zooms
constexpr double kPointGrab = 6.0;  // pixels from a point that still take it

QColor opaqueColor(glm::dvec3 c) { return QColor::fromRgbF(float(c.r), float(c.g), float(c.b)); }

}  // namespace

TfCurveView::TfCurveView(TfEditorModel& model, QWidget* parent) : QWidget(parent), model_(model) {
  setObjectName("tfCurve");
  setMinimumSize(360, 180);
  setFocusPolicy(Qt::StrongFocus);
  setToolTip(
      "Opacity over HU, on the volume's histogram. Click: add a point; drag: move it; right "
      "click or Delete: remove it. Colour bar: click adds a colour point, double click picks "
      "its colour. Wheel: zoom the HU axis about the mouse; drag the HU axis (or the middle "
      "button): pan");
  onModelChange<>(this, model_.changed, [this] {
    // Indices may have gone with an undo or a file: keep the selection only if it exists.
    if (selection_) {
      size_t n = selection_->list == List::Opacity ? model_.property().opacity.size()
                                                   : model_.property().color.size();
      if (selection_->index >= n) select(std::nullopt);
    }
    update();
  });
}

void TfCurveView::setHistogram(StoredHistogram h, double slope, double intercept) {
  histogram_ = std::move(h);
  slope_ = slope;
  intercept_ = intercept;
  update();
}

void TfCurveView::setLogHistogram(bool on) {
  logHistogram_ = on;
  update();
}

void TfCurveView::setHuRange(double lo, double hi) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return;
  if (hu_ == AxisRange{lo, hi}) return;
  hu_ = {lo, hi};
  update();
  if (rangeChanged) rangeChanged();
}

double TfCurveView::huPerPixel() const { return hu_.span() / curveArea().width(); }

void TfCurveView::fitVisible() {
  if (histogram_.empty()) return;
  AxisRange r = visibleHuRange(histogram_, slope_, intercept_);
  setHuRange(r.lo, r.hi);
}

void TfCurveView::setOpacityTop(double top) {
  top_ = std::clamp(top, 0.001, 1.0);
  update();
}

QRectF TfCurveView::curveArea() const {
  return QRectF(kCurveMargin, kCurveMargin, width() - 2 * kCurveMargin,
                height() - 3 * kCurveMargin - kBarHeight - kAxisHeight);
}

QRectF TfCurveView::axisStrip() const {
  QRectF b = colorBar();
  return QRectF(b.left(), b.bottom(), b.width(), kAxisHeight);
}

QRectF TfCurveView::colorBar() const {
  QRectF c = curveArea();
  return QRectF(c.left(), c.bottom() + kCurveMargin, c.width(), kBarHeight);
}

double TfCurveView::xOf(double hu) const {
  QRectF a = curveArea();
  return axisPixel(hu_, hu, a.left(), a.width());
}

double TfCurveView::yOf(double opacity) const {
  QRectF a = curveArea();
  return a.bottom() - std::min(opacity / top_, 1.0) * a.height();
}

double TfCurveView::huAt(double x) const {
  QRectF a = curveArea();
  return axisValue(hu_, x, a.left(), a.width());
}

double TfCurveView::opacityAt(double y) const {
  QRectF a = curveArea();
  return std::clamp((a.bottom() - y) / a.height(), 0.0, 1.0) * top_;
}

void TfCurveView::select(std::optional<Selection> s) {
  selection_ = s;
  update();
  if (selectionChanged) selectionChanged();
}

void TfCurveView::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const QRectF area = curveArea(), bar = colorBar();
  p.fillRect(rect(), palette().window());
  p.fillRect(area, QColor(24, 24, 28));
  const VolumeProperty& vp = model_.property();
  const int columns = std::max(1, int(area.width()));
  // The histogram: voxels per column of HU, scaled to the fullest column in view.
  if (!histogram_.empty()) {
    std::vector<double> heights(size_t(columns), 0.0);
    double most = 0.0;
    for (int c = 0; c < columns; ++c) {
      double a = (huAt(area.left() + c) - intercept_) / slope_;
      double b = (huAt(area.left() + c + 1) - intercept_) / slope_;
      double n = double(histogram_.countIn(std::min(a, b), std::max(a, b) - 1e-9));
      heights[size_t(c)] = logHistogram_ ? std::log1p(n) : n;
      most = std::max(most, heights[size_t(c)]);
    }
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(90, 90, 100));
    for (int c = 0; c < columns && most > 0.0; ++c) {
      double h = heights[size_t(c)] / most * area.height();
      p.drawRect(QRectF(area.left() + c, area.bottom() - h, 1.0, h));
    }
  }
  // The opacity curve, filled with the colour it has at each HU.
  QPainterPath curve;
  for (int c = 0; c <= columns; ++c) {
    double x = area.left() + c, y = yOf(voxray::opacityAt(vp, huAt(x)));
    if (c == 0)
      curve.moveTo(x, y);
    else
      curve.lineTo(x, y);
  }
  QLinearGradient fill(area.left(), 0, area.right(), 0);
  for (int k = 0; k <= 32; ++k) {
    double f = k / 32.0;
    QColor c = opaqueColor(colorAt(vp, hu_.lo + f * hu_.span()));
    c.setAlpha(110);
    fill.setColorAt(f, c);
  }
  QPainterPath under = curve;
  under.lineTo(area.right(), area.bottom());
  under.lineTo(area.left(), area.bottom());
  under.closeSubpath();
  p.save();
  p.setClipRect(area);
  p.fillPath(under, fill);
  p.setPen(QPen(QColor(240, 240, 240), 1.5));
  p.setBrush(Qt::NoBrush);
  p.drawPath(curve);
  for (size_t i = 0; i < vp.opacity.size(); ++i) {
    bool chosen = selection_ && selection_->list == List::Opacity && selection_->index == i;
    p.setBrush(chosen ? QColor(255, 200, 40) : QColor(250, 250, 250));
    p.setPen(QPen(Qt::black, 1.0));
    p.drawEllipse(QPointF(xOf(vp.opacity[i].x), yOf(vp.opacity[i].opacity)), 4.5, 4.5);
  }
  p.restore();
  // The colour bar and its points.
  for (int c = 0; c < columns; ++c)
    p.fillRect(QRectF(bar.left() + c, bar.top(), 1.0, bar.height()),
               opaqueColor(colorAt(vp, huAt(bar.left() + c))));
  p.save();
  p.setClipRect(bar.adjusted(-kPointGrab, 0, kPointGrab, 0));
  for (size_t i = 0; i < vp.color.size(); ++i) {
    bool chosen = selection_ && selection_->list == List::Color && selection_->index == i;
    double x = xOf(vp.color[i].hu);
    QPolygonF mark(
        {QPointF(x, bar.top()), QPointF(x - 5, bar.bottom()), QPointF(x + 5, bar.bottom())});
    p.setBrush(opaqueColor(vp.color[i].rgb));
    p.setPen(QPen(chosen ? QColor(255, 200, 40) : QColor(20, 20, 20), chosen ? 2.0 : 1.0));
    p.drawPolygon(mark);
  }
  p.restore();
  // The HU axis: its two ends and its middle.
  const QRectF axis = axisStrip();
  p.setPen(palette().windowText().color());
  p.drawText(axis, Qt::AlignLeft | Qt::AlignVCenter, QString::number(hu_.lo, 'f', 0));
  p.drawText(axis, Qt::AlignHCenter | Qt::AlignVCenter,
             QString("%1 HU").arg(0.5 * (hu_.lo + hu_.hi), 0, 'f', 0));
  p.drawText(axis, Qt::AlignRight | Qt::AlignVCenter, QString::number(hu_.hi, 'f', 0));
}

std::optional<TfCurveView::Selection> TfCurveView::pointAt(QPointF pos) const {
  const VolumeProperty& vp = model_.property();
  std::optional<Selection> best;
  double bestDistance = kPointGrab;
  if (colorBar().adjusted(-kPointGrab, -kPointGrab, kPointGrab, kPointGrab).contains(pos)) {
    for (size_t i = 0; i < vp.color.size(); ++i) {
      double d = std::abs(xOf(vp.color[i].hu) - pos.x());
      if (d <= bestDistance) best = Selection{List::Color, i}, bestDistance = d;
    }
    return best;
  }
  for (size_t i = 0; i < vp.opacity.size(); ++i) {
    double d = std::hypot(xOf(vp.opacity[i].x) - pos.x(), yOf(vp.opacity[i].opacity) - pos.y());
    if (d <= bestDistance) best = Selection{List::Opacity, i}, bestDistance = d;
  }
  return best;
}

void TfCurveView::mousePressEvent(QMouseEvent* e) {
  const QPointF pos = e->position();
  std::optional<Selection> hit = pointAt(pos);
  if (e->button() == Qt::RightButton) {
    if (hit) {
      select(hit);
      removeSelected();
    }
    return;
  }
  if (e->button() == Qt::MiddleButton ||
      (e->button() == Qt::LeftButton && axisStrip().contains(pos))) {
    pan_ = {pos.x(), hu_};
    return;
  }
  if (e->button() != Qt::LeftButton) return;
  model_.beginGesture();
  dragging_ = true;
  if (!hit && curveArea().contains(pos))
    hit = Selection{List::Opacity, model_.addOpacityPoint(huAt(pos.x()), opacityAt(pos.y()))};
  else if (!hit && colorBar().contains(pos))
    hit = Selection{List::Color, model_.addColorPoint(huAt(pos.x()))};
  select(hit);
}

void TfCurveView::mouseMoveEvent(QMouseEvent* e) {
  if (pan_) {
    AxisRange r = panByPixels(pan_->second, e->position().x() - pan_->first, curveArea().width());
    setHuRange(r.lo, r.hi);
    return;
  }
  if (!dragging_ || !selection_) return;
  const QPointF pos = e->position();
  if (selection_->list == List::Opacity)
    model_.moveOpacityPoint(selection_->index, huAt(pos.x()), opacityAt(pos.y()));
  else
    model_.moveColorPoint(selection_->index, huAt(pos.x()));
}

void TfCurveView::mouseReleaseEvent(QMouseEvent*) {
  pan_.reset();
  if (!dragging_) return;
  dragging_ = false;
  model_.endGesture();
}

void TfCurveView::mouseDoubleClickEvent(QMouseEvent* e) {
  std::optional<Selection> hit = pointAt(e->position());
  if (hit && hit->list == List::Color) pickColor(hit->index);
}

void TfCurveView::wheelEvent(QWheelEvent* e) {
  // Over the curve, the axis or with Ctrl alike: the wheel has no other use here.
  AxisRange r =
      zoomAbout(hu_, huAt(e->position().x()), wheelZoomFactor(e->angleDelta().y() / 120.0),
                kCurveMinSpanHu, kCurveMaxSpanHu);
  setHuRange(r.lo, r.hi);
}

void TfCurveView::keyPressEvent(QKeyEvent* e) {
  if (e->key() == Qt::Key_Delete || e->key() == Qt::Key_Backspace)
    removeSelected();
  else
    QWidget::keyPressEvent(e);
}

void TfCurveView::removeSelected() {
  if (!selection_) return;
  Selection s = *selection_;
  select(std::nullopt);
  if (s.list == List::Opacity)
    model_.removeOpacityPoint(s.index);
  else
    model_.removeColorPoint(s.index);
}

void TfCurveView::pickColor(size_t index) {
  QColor c = QColorDialog::getColor(opaqueColor(model_.property().color[index].rgb), this,
                                    "Colour of the point");
  if (c.isValid()) model_.setPointColor(index, {c.redF(), c.greenF(), c.blueF()});
}

}  // namespace voxray::ui
