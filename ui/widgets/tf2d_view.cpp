#include "tf2d_view.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <QColorDialog>
#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include "coupling.h"

namespace voxray::ui {

namespace {

constexpr double kPlotMargin = 8.0;
constexpr double kCornerGrab = 6.0;  // pixels from a corner that still take its handle
constexpr double kStrip = 16.0;      // the axes' strips beside the plot
constexpr double kPlotMinSpanHu = 1.0, kMinSpanG = 0.1, kMaxSpan = 1e6;  // how far the axes zoom

QColor plotColor(glm::dvec3 c, double alpha = 1.0) {
  return QColor::fromRgbF(float(c.r), float(c.g), float(c.b), float(alpha));
}

}  // namespace

Tf2dView::Tf2dView(TfEditorModel& model, QWidget* parent) : QWidget(parent), model_(model) {
  setObjectName("tf2dView");
  setMinimumSize(360, 200);
  setFocusPolicy(Qt::StrongFocus);
  setToolTip(
      "The 2D transfer function over HU (across) and gradient magnitude in HU/mm (up), on the "
      "volume's 2D histogram: a boundary arcs up between the two materials it separates. Right "
      "click: add a rectangle or triangle, delete, colour. Drag a shape to move it, a corner "
      "to resize it; Delete removes the selected one. Wheel: zoom (over an axis' strip: that "
      "axis); drag an axis' strip or with the middle button: pan. Shapes replace the 1D curve "
      "in dvr");
  onModelChange<>(this, model_.changed, [this] {
    if (selection_ && *selection_ >= model_.property().tf2d.primitives.size()) select(std::nullopt);
    update();
  });
}

void Tf2dView::setHistogram(const Tf2dHistogram& h) {
  histogram_ = h;
  if (h.empty()) {
    image_ = QImage();
    fullHu_ = {-1024.0, 3071.0};
    fullG_ = 200.0;
  } else {
    fullHu_ = {h.huLo, h.huHi};
    fullG_ = h.gradientMax;
    std::vector<float> grey = h.logImage();
    image_ =
        QImage(Tf2dHistogram::kValueBins, Tf2dHistogram::kGradientBins, QImage::Format_Grayscale8);
    for (int row = 0; row < Tf2dHistogram::kGradientBins; ++row) {
      uchar* line = image_.scanLine(Tf2dHistogram::kGradientBins - 1 - row);
      for (int c = 0; c < Tf2dHistogram::kValueBins; ++c)
        line[c] =
            uchar(std::lround(255.0 * grey[size_t(row) * Tf2dHistogram::kValueBins + size_t(c)]));
    }
  }
  resetRanges();
}

void Tf2dView::setRanges(AxisRange hu, AxisRange g) {
  if (!(hu.span() > 0.0) || !(g.span() > 0.0)) return;
  hu_ = hu;
  g_ = g;
  update();
}

void Tf2dView::resetRanges() { setRanges(fullHu_, {0.0, fullG_}); }

void Tf2dView::fitVisible() {
  if (histogram_.empty()) return;
  constexpr int kCols = Tf2dHistogram::kValueBins, kRows = Tf2dHistogram::kGradientBins;
  std::vector<uint64_t> columns(kCols, 0), rows(kRows, 0);
  for (int r = 0; r < kRows; ++r)
    for (int c = 0; c < kCols; ++c) {
      columns[size_t(c)] += histogram_.at(c, r);
      rows[size_t(r)] += histogram_.at(c, r);
    }
  AxisRange hu = occupiedRange(columns, fullHu_.lo, fullHu_.hi, kVisibleFraction);
  AxisRange g = occupiedRange(rows, 0.0, fullG_, kVisibleFraction);
  setRanges(hu, {0.0, g.hi});
}

QRectF Tf2dView::plotArea() const {
  return QRectF(kPlotMargin + kStrip, kPlotMargin, width() - 2 * kPlotMargin - kStrip,
                height() - 2 * kPlotMargin - kStrip);
}

QRectF Tf2dView::huStrip() const {
  QRectF a = plotArea();
  return QRectF(a.left(), a.bottom(), a.width(), kStrip);
}

QRectF Tf2dView::gradientStrip() const {
  QRectF a = plotArea();
  return QRectF(a.left() - kStrip, a.top(), kStrip, a.height());
}

// The gradient axis runs up: from the plot's bottom over minus its height.
double Tf2dView::xOf(double hu) const {
  QRectF a = plotArea();
  return axisPixel(hu_, hu, a.left(), a.width());
}

double Tf2dView::yOf(double g) const {
  QRectF a = plotArea();
  return axisPixel(g_, g, a.bottom(), -a.height());
}

double Tf2dView::huAt(double x) const {
  QRectF a = plotArea();
  return axisValue(hu_, x, a.left(), a.width());
}

double Tf2dView::gAt(double y) const {
  QRectF a = plotArea();
  return axisValue(g_, y, a.bottom(), -a.height());
}

void Tf2dView::select(std::optional<size_t> i) {
  if (i == selection_) return;
  selection_ = i;
  update();
  if (selectionChanged) selectionChanged();
}

std::optional<Tf2dHit> Tf2dView::hitAt(QPointF pos) const {
  QRectF a = plotArea();
  double huTol = kCornerGrab / a.width() * hu_.span(), gTol = kCornerGrab / a.height() * g_.span();
  return tf2dHitTest(model_.property().tf2d, huAt(pos.x()), gAt(pos.y()), huTol, gTol);
}

void Tf2dView::addAt(Tf2dShape shape, QPointF pos) {
  // A new shape spans an eighth of the HU axis and a quarter of the gradient axis, centred on
  // the mouse (a triangle's apex stays at |gradient| 0 whatever its box: tf2d.h).
  Tf2dPrimitive p;
  p.shape = shape;
  double hu = huAt(pos.x()), g = std::max(0.0, gAt(pos.y()));
  double halfHu = hu_.span() / 16.0, halfG = g_.span() / 8.0;
  p.hu0 = hu - halfHu;
  p.hu1 = hu + halfHu;
  p.g0 = shape == Tf2dShape::Triangle ? 0.0 : std::max(0.0, g - halfG);
  p.g1 = std::max(g + halfG, p.g0 + 2.0 * halfG);
  p.rgb = {1.0, 0.85, 0.6};
  p.opacity = 0.5;
  p.soft = 0.3;
  select(model_.addTf2dPrimitive(p, fullG_));
}

QMenu* Tf2dView::menuAt(QPointF pos) {
  auto* menu = new QMenu(this);
  QAction* rect =
      menu->addAction("Add rectangle", this, [this, pos] { addAt(Tf2dShape::Rectangle, pos); });
  rect->setObjectName("tf2dAddRect");
  QAction* tri = menu->addAction("Add triangle (a boundary)", this,
                                 [this, pos] { addAt(Tf2dShape::Triangle, pos); });
  tri->setObjectName("tf2dAddTriangle");
  std::optional<Tf2dHit> hit = hitAt(pos);
  if (hit) select(hit->index);
  menu->addSeparator();
  size_t index = hit ? hit->index : 0;
  QAction* colour = menu->addAction("Colour…", this, [this, index] { pickColor(index); });
  colour->setObjectName("tf2dColor");
  colour->setEnabled(bool(hit));
  QAction* del = menu->addAction("Delete", this, [this, index] {
    select(std::nullopt);
    model_.removeTf2dPrimitive(index);
  });
  del->setObjectName("tf2dDelete");
  del->setEnabled(bool(hit));
  return menu;
}

void Tf2dView::pickColor(size_t i) {
  if (i >= model_.property().tf2d.primitives.size()) return;
  QColor picked = QColorDialog::getColor(plotColor(model_.property().tf2d.primitives[i].rgb), this,
                                         "Colour of the shape");
  if (picked.isValid()) model_.setTf2dColor(i, {picked.redF(), picked.greenF(), picked.blueF()});
}

void Tf2dView::contextMenuEvent(QContextMenuEvent* e) {
  QMenu* menu = menuAt(e->pos());
  menu->setAttribute(Qt::WA_DeleteOnClose);
  menu->popup(e->globalPos());
}

void Tf2dView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), palette().window());
  QRectF a = plotArea();
  painter.fillRect(a, Qt::black);
  painter.save();
  painter.setClipRect(a);
  if (!image_.isNull())
    painter.drawImage(
        QRectF(QPointF(xOf(fullHu_.lo), yOf(fullG_)), QPointF(xOf(fullHu_.hi), yOf(0.0))), image_);
  painter.setRenderHint(QPainter::Antialiasing);
  const auto& ps = model_.property().tf2d.primitives;
  for (size_t k = 0; k < ps.size(); ++k) {
    const Tf2dPrimitive& p = ps[k];
    QPainterPath path;
    if (p.shape == Tf2dShape::Rectangle) {
      path.addRect(QRectF(QPointF(xOf(p.hu0), yOf(p.g1)), QPointF(xOf(p.hu1), yOf(p.g0))));
    } else {
      // The triangle cut to [g0, g1]: its sides run from the apex (middle, 0) to the top
      // corners.
      double mid = 0.5 * (p.hu0 + p.hu1), half = 0.5 * (p.hu1 - p.hu0);
      double w0 = half * p.g0 / p.g1;
      path.moveTo(xOf(mid - w0), yOf(p.g0));
      path.lineTo(xOf(p.hu0), yOf(p.g1));
      path.lineTo(xOf(p.hu1), yOf(p.g1));
      path.lineTo(xOf(mid + w0), yOf(p.g0));
      path.closeSubpath();
    }
    painter.fillPath(path, plotColor(p.rgb, 0.15 + 0.35 * p.opacity));
    bool selected = selection_ && *selection_ == k;
    painter.setPen(QPen(plotColor(p.rgb), selected ? 2.5 : 1.2));
    painter.drawPath(path);
    if (selected) {
      painter.setBrush(Qt::white);
      painter.setPen(QPen(Qt::black, 1.0));
      for (QPointF c : {QPointF(xOf(p.hu0), yOf(p.g0)), QPointF(xOf(p.hu1), yOf(p.g0)),
                        QPointF(xOf(p.hu0), yOf(p.g1)), QPointF(xOf(p.hu1), yOf(p.g1))})
        painter.drawRect(QRectF(c - QPointF(3, 3), QSizeF(6, 6)));
      painter.setBrush(Qt::NoBrush);
    }
  }
  painter.restore();
  // Axis labels in white with a black shadow: readable on dark and bright bins alike.
  const QRectF labels = a.adjusted(4, 2, -4, -2);
  // The gradient axis' bottom value (0 until panned or zoomed) sits a line above the HU's.
  const QRectF above = labels.adjusted(0, 0, 0, -painter.fontMetrics().height());
  const std::tuple<QRectF, int, QString> texts[] = {
      {labels, Qt::AlignLeft | Qt::AlignTop, QString("|∇| %1 HU/mm").arg(g_.hi, 0, 'f', 0)},
      {above, Qt::AlignLeft | Qt::AlignBottom, QString("|∇| %1").arg(g_.lo, 0, 'f', 0)},
      {labels, Qt::AlignLeft | Qt::AlignBottom, QString("%1 HU").arg(hu_.lo, 0, 'f', 0)},
      {labels, Qt::AlignRight | Qt::AlignBottom, QString("%1 HU").arg(hu_.hi, 0, 'f', 0)}};
  for (const auto& [box, align, text] : texts) {
    painter.setPen(Qt::black);
    painter.drawText(box.translated(1, 1), align, text);
    painter.setPen(Qt::white);
    painter.drawText(box, align, text);
  }
}

void Tf2dView::mousePressEvent(QMouseEvent* e) {
  const QPointF pos = e->position();
  const bool onHu = huStrip().contains(pos), onG = gradientStrip().contains(pos);
  if (e->button() == Qt::MiddleButton || (e->button() == Qt::LeftButton && (onHu || onG))) {
    const bool both = e->button() == Qt::MiddleButton;
    pan_ = Pan{pos, hu_, g_, both || onHu, both || onG};
    return;
  }
  if (e->button() != Qt::LeftButton) return;
  drag_ = hitAt(e->position());
  select(drag_ ? std::optional<size_t>(drag_->index) : std::nullopt);
  if (!drag_) return;
  dragFrom_ = e->position();
  dragStart_ = model_.property().tf2d.primitives[drag_->index];
  model_.beginGesture();
}

void Tf2dView::mouseMoveEvent(QMouseEvent* e) {
  if (pan_) {
    const QRectF a = plotArea();
    const QPointF d = e->position() - pan_->from;
    setRanges(pan_->panHu ? panByPixels(pan_->hu, d.x(), a.width()) : hu_,
              pan_->panG ? panByPixels(pan_->g, d.y(), -a.height()) : g_);
    return;
  }
  if (!drag_) return;
  QPointF at = e->position();
  if (drag_->part == Tf2dPart::Body) {
    // From the shape as the drag found it, by the whole way the mouse went: the shape stays
    // under the mouse (where |gradient| 0 stopped it, it catches up when the mouse comes back).
    Tf2dPrimitive q =
        tf2dMoved(dragStart_, huAt(at.x()) - huAt(dragFrom_.x()), gAt(at.y()) - gAt(dragFrom_.y()));
    model_.setTf2dExtent(drag_->index, q.hu0, q.hu1, q.g0, q.g1);
  } else {
    model_.resizeTf2dPrimitive(drag_->index, drag_->part, huAt(at.x()), gAt(at.y()));
  }
}

void Tf2dView::wheelEvent(QWheelEvent* e) {
  const QPointF pos = e->position();
  const bool onHu = huStrip().contains(pos), onG = gradientStrip().contains(pos);
  const double f = wheelZoomFactor(e->angleDelta().y() / 120.0);
  // Over one axis' strip: that axis; elsewhere (Ctrl or not): both, about the cursor.
  setRanges(onG ? hu_ : zoomAbout(hu_, huAt(pos.x()), f, kPlotMinSpanHu, kMaxSpan),
            onHu ? g_ : zoomAbout(g_, gAt(pos.y()), f, kMinSpanG, kMaxSpan));
}

void Tf2dView::mouseReleaseEvent(QMouseEvent*) {
  pan_.reset();
  if (!drag_) return;
  drag_.reset();
  model_.endGesture();
}

void Tf2dView::keyPressEvent(QKeyEvent* e) {
  if ((e->key() == Qt::Key_Delete || e->key() == Qt::Key_Backspace) && selection_) {
    size_t i = *selection_;
    select(std::nullopt);
    model_.removeTf2dPrimitive(i);
    return;
  }
  QWidget::keyPressEvent(e);
}

}  // namespace voxray::ui
