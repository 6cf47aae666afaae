#include "measure_overlay.h"

#include <algorithm>

#include <QRegularExpression>

namespace voxray::ui {

namespace {

const QColor kMeasureColor(80, 230, 255);
const QColor kSelectedColor(255, 230, 60);

void drawHandle(QPainter& p, QPointF at) {
  p.drawRect(
      QRectF(at.x() - kHandleRadius, at.y() - kHandleRadius, 2 * kHandleRadius, 2 * kHandleRadius));
}

constexpr double kLabelOffsetX = 8.0, kLabelOffsetY = 6.0;  // from the point labelled
constexpr double kHaloMargin = 1.0;

void drawLabel(QPainter& p, const QRectF& bounds, QPointF at, const std::string& text) {
  const QFontMetricsF fm(p.font());
  const MeasureLabel label = layoutMeasureLabel(fm, bounds, at, QString::fromStdString(text));
  // A dark halo keeps the numbers readable on bone and on air alike.
  const QPen pen = p.pen();
  for (qsizetype i = 0; i < label.lines.size(); ++i) {
    const QPointF pos(label.rect.left(), label.rect.top() + fm.ascent() + i * fm.lineSpacing());
    p.setPen(Qt::black);
    for (QPointF d : {QPointF(1, 1), QPointF(-1, -1), QPointF(1, -1), QPointF(-1, 1)})
      p.drawText(pos + d, label.lines[i]);
    p.setPen(pen);
    p.drawText(pos, label.lines[i]);
  }
}

void drawCross(QPainter& p, QPointF at) {
  p.drawLine(at - QPointF(6, 0), at + QPointF(6, 0));
  p.drawLine(at - QPointF(0, 6), at + QPointF(0, 6));
}

}  // namespace

MeasureLabel layoutMeasureLabel(const QFontMetricsF& fm, const QRectF& bounds, QPointF at,
                                const QString& text) {
  const QRectF inside = bounds.adjusted(kHaloMargin, kHaloMargin, -kHaloMargin, -kHaloMargin);
  MeasureLabel label;
  // Pieces ending in ", " or a double space: "mean 12.3  SD 4.5  …, 123.4 mm², 456 px".
  static const QRegularExpression kBreaks("(?<=, )|(?<=  )");
  QString line;
  for (const QString& piece : text.split(kBreaks, Qt::SkipEmptyParts)) {
    const QString longer = line + piece;
    if (!line.isEmpty() && fm.horizontalAdvance(longer.trimmed()) > inside.width()) {
      label.lines << line.trimmed();
      line = piece;
    } else {
      line = longer;
    }
  }
  if (!line.trimmed().isEmpty() || label.lines.isEmpty()) label.lines << line.trimmed();
  double width = 0.0;
  for (const QString& l : label.lines) width = std::max(width, fm.horizontalAdvance(l));
  const double height = double(label.lines.size()) * fm.lineSpacing();
  QPointF topLeft(at.x() + kLabelOffsetX, at.y() - kLabelOffsetY - fm.ascent());
  if (topLeft.x() + width > inside.right())  // no room on the right: the left side
    topLeft.setX(at.x() - kLabelOffsetX - width);
  topLeft.setX(
      std::clamp(topLeft.x(), inside.left(), std::max(inside.left(), inside.right() - width)));
  topLeft.setY(
      std::clamp(topLeft.y(), inside.top(), std::max(inside.top(), inside.bottom() - height)));
  label.rect = QRectF(topLeft, QSizeF(width, height));
  return label;
}

void drawSliceMeasurements(QPainter& p, const QRectF& bounds, const Volume& v,
                           const MeasurementModel& model, const SliceAxes& axes, int slice,
                           const VoxelToWidget& toWidget) {
  p.save();
  p.setBrush(Qt::NoBrush);
  for (const Measurement& m : model.items()) {
    const QColor color = m.id == model.selected() ? kSelectedColor : kMeasureColor;
    p.setPen(QPen(color, 1.5));
    if (!shownOnSlice(m, axes, slice)) {
      // A 3D pick crossing this slice: mark its points that lie here.
      for (const auto& pt : m.points)
        if (m.normalAxis < 0 && pointOnSlice(pt, axes, slice)) drawCross(p, toWidget(pt));
      continue;
    }
    std::vector<QPointF> w;
    for (const auto& pt : m.points) w.push_back(toWidget(pt));
    switch (m.kind) {
      case MeasureKind::Distance:
        p.drawLine(w[0], w[1]);
        break;
      case MeasureKind::Angle:
        p.drawLine(w[0], w[1]);
        p.drawLine(w[1], w[2]);
        break;
      case MeasureKind::Ellipse:
        p.drawEllipse(QRectF(w[0], w[1]).normalized());
        break;
      case MeasureKind::Rect:
        p.drawRect(QRectF(w[0], w[1]).normalized());
        break;
    }
    for (QPointF h : w) drawHandle(p, h);
    drawLabel(p, bounds, w.back(), measurementText(v, m));
  }
  if (model.pendingPick() && pointOnSlice(*model.pendingPick(), axes, slice)) {
    p.setPen(QPen(kSelectedColor, 1.5));
    drawCross(p, toWidget(*model.pendingPick()));
  }
  p.restore();
}

void drawPickedMeasurements(QPainter& p, const QRectF& bounds, const Volume& v,
                            const MeasurementModel& model, const VoxelToScreen& toWidget) {
  p.save();
  for (const Measurement& m : model.items()) {
    if (m.normalAxis >= 0) continue;
    const auto a = toWidget(m.points[0]), b = toWidget(m.points[1]);
    if (!a || !b) continue;
    p.setPen(QPen(m.id == model.selected() ? kSelectedColor : kMeasureColor, 2));
    p.drawLine(*a, *b);
    drawCross(p, *a);
    drawCross(p, *b);
    drawLabel(p, bounds, *b, measurementText(v, m));
  }
  if (model.pendingPick())
    if (auto a = toWidget(*model.pendingPick())) {
      p.setPen(QPen(kSelectedColor, 2));
      drawCross(p, *a);
    }
  p.restore();
}

}  // namespace voxray::ui
