#include "annotation_overlay.h"

#include <cmath>

#include "measure_overlay.h"

namespace voxray::ui {

namespace {

constexpr double kHeadLength = 12.0, kHeadHalfWidth = 5.0;  // widget pixels
constexpr double kShaftWidth = 2.0;

void drawText(QPainter& p, const QRectF& bounds, QPointF at, const std::string& text,
              const QColor& color) {
  const QFontMetricsF fm(p.font());
  const MeasureLabel label = layoutMeasureLabel(fm, bounds, at, QString::fromStdString(text));
  for (qsizetype i = 0; i < label.lines.size(); ++i) {
    const QPointF pos(label.rect.left(), label.rect.top() + fm.ascent() + i * fm.lineSpacing());
    p.setPen(Qt::black);  // a halo: readable on bone and on air alike
    for (QPointF d : {QPointF(1, 1), QPointF(-1, -1), QPointF(1, -1), QPointF(-1, 1)})
      p.drawText(pos + d, label.lines[i]);
    p.setPen(color);
    p.drawText(pos, label.lines[i]);
  }
}

}  // namespace

void drawArrow(QPainter& p, QPointF head, QPointF tail, const QColor& color) {
  const QPointF d = head - tail;
  const double len = std::hypot(d.x(), d.y());
  p.save();
  p.setPen(QPen(color, kShaftWidth, Qt::SolidLine, Qt::RoundCap));
  p.setBrush(color);
  if (len < 1e-6) {
    p.drawEllipse(head, kShaftWidth, kShaftWidth);
    p.restore();
    return;
  }
  const QPointF u = d / len, n(-u.y(), u.x());
  const double headLen = std::min(kHeadLength, len);
  const QPointF base = head - u * headLen;
  p.drawLine(tail, base);
  p.setPen(QPen(color, 1.0));
  p.drawPolygon(QPolygonF({head, base + n * kHeadHalfWidth, base - n * kHeadHalfWidth}));
  p.restore();
}

void drawSliceAnnotations(QPainter& p, const QRectF& bounds, const Volume& v,
                          const AnnotationModel& model, const SliceAxes& axes, int slice,
                          const MmToWidget& toWidget) {
  p.save();
  for (const Annotation& a : model.items()) {
    if (!annotationOnSlice(a, v, axes, slice)) continue;
    const QColor color = a.id == model.selected() ? kAnnotationSelectedColor : kAnnotationColor;
    const QPointF anchor = toWidget(a.anchorMm);
    if (a.tailMm) {
      const QPointF tail = toWidget(*a.tailMm);
      drawArrow(p, anchor, tail, color);
      if (!a.text.empty()) drawText(p, bounds, tail, a.text, color);
    } else {
      drawText(p, bounds, anchor, a.text, color);
    }
  }
  p.restore();
}

}  // namespace voxray::ui
