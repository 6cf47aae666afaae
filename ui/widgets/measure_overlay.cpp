#include "measure_overlay.h"

namespace voxray::ui {

namespace {

const QColor kMeasureColor(80, 230, 255);
const QColor kSelectedColor(255, 230, 60);

void drawHandle(QPainter& p, QPointF at) {
  p.drawRect(
      QRectF(at.x() - kHandleRadius, at.y() - kHandleRadius, 2 * kHandleRadius, 2 * kHandleRadius));
}

void drawLabel(QPainter& p, QPointF at, const std::string& text) {
  // A dark halo keeps the numbers readable on bone and on air alike.
  const QString s = QString::fromStdString(text);
  const QPointF pos = at + QPointF(8, -6);
  const QPen pen = p.pen();
  p.setPen(Qt::black);
  for (QPointF d : {QPointF(1, 1), QPointF(-1, -1), QPointF(1, -1), QPointF(-1, 1)})
    p.drawText(pos + d, s);
  p.setPen(pen);
  p.drawText(pos, s);
}

void drawCross(QPainter& p, QPointF at) {
  p.drawLine(at - QPointF(6, 0), at + QPointF(6, 0));
  p.drawLine(at - QPointF(0, 6), at + QPointF(0, 6));
}

}  // namespace

void drawSliceMeasurements(QPainter& p, const Volume& v, const MeasurementModel& model,
                           const SliceAxes& axes, int slice, const VoxelToWidget& toWidget) {
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
    drawLabel(p, w.back(), measurementText(v, m));
  }
  if (model.pendingPick() && pointOnSlice(*model.pendingPick(), axes, slice)) {
    p.setPen(QPen(kSelectedColor, 1.5));
    drawCross(p, toWidget(*model.pendingPick()));
  }
  p.restore();
}

void drawPickedMeasurements(QPainter& p, const Volume& v, const MeasurementModel& model,
                            const VoxelToScreen& toWidget) {
  p.save();
  for (const Measurement& m : model.items()) {
    if (m.normalAxis >= 0) continue;
    const auto a = toWidget(m.points[0]), b = toWidget(m.points[1]);
    if (!a || !b) continue;
    p.setPen(QPen(m.id == model.selected() ? kSelectedColor : kMeasureColor, 2));
    p.drawLine(*a, *b);
    drawCross(p, *a);
    drawCross(p, *b);
    drawLabel(p, *b, measurementText(v, m));
  }
  if (model.pendingPick())
    if (auto a = toWidget(*model.pendingPick())) {
      p.setPen(QPen(kSelectedColor, 2));
      drawCross(p, *a);
    }
  p.restore();
}

}  // namespace voxray::ui
