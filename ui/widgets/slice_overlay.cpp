#include "slice_overlay.h"

#include <algorithm>
#include <cmath>

#include "volume_overlay.h"

namespace voxray::ui {

double niceLengthMm(double target) {
  if (target <= 0) return 1.0;
  double power = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * power <= target) return m * power;
  return power;
}

ScaleBar scaleBarLayout(const QFontMetricsF& fm, double mmPerPixel, const QRect& r) {
  ScaleBar out;
  const double mm = niceLengthMm(0.2 * r.width() * mmPerPixel);
  const double px = mm / mmPerPixel;
  const QPointF end(r.right() - 10, r.bottom() - 22);
  out.bar = QLineF(end - QPointF(px, 0), end);
  out.text = QString("%1 mm").arg(mm);
  // Centred under the bar but never narrower than its text (a label as wide as a short bar
  // was clipped to "0 mr"), and kept inside the view's right edge.
  const double w = std::max(px, std::ceil(fm.horizontalAdvance(out.text)) + 2.0);
  double left = end.x() - px / 2 - w / 2;
  left = std::min(left, double(r.right()) - 2.0 - w);
  out.label = QRectF(left, end.y() + 2, w, std::ceil(fm.height()) + 1.0);
  return out;
}

namespace {

// The orientation letters' colour: none of the plane colours (yellow, green, red) nor the
// clip box's magenta, so that a crosshair line is never read as part of a letter.
const QColor kLetterColor(150, 215, 255);
constexpr int kLetterMargin = 4;

void drawLabels(QPainter& p, const SliceAxes& a, const QRect& r) {
  QFont f = p.font();
  f.setBold(true);
  p.setFont(f);
  p.setPen(kLetterColor);
  const auto& l = a.labels;  // left, right, top, bottom
  const int m = kLetterMargin;
  p.drawText(r.adjusted(m, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter,
             QString::fromStdString(l[0]));
  p.drawText(r.adjusted(0, 0, -m, 0), Qt::AlignRight | Qt::AlignVCenter,
             QString::fromStdString(l[1]));
  p.drawText(r.adjusted(0, m, 0, 0), Qt::AlignHCenter | Qt::AlignTop, QString::fromStdString(l[2]));
  p.drawText(r.adjusted(0, 0, 0, -m), Qt::AlignHCenter | Qt::AlignBottom,
             QString::fromStdString(l[3]));
  f.setBold(false);
  p.setFont(f);
}

void drawScaleBar(QPainter& p, double mmPerPixel, const QRect& r) {
  const ScaleBar bar = scaleBarLayout(QFontMetricsF(p.font()), mmPerPixel, r);
  const QPointF start = bar.bar.p1(), end = bar.bar.p2();
  p.setPen(QPen(Qt::white, 2));
  p.drawLine(start, end);
  p.drawLine(start, start - QPointF(0, 4));
  p.drawLine(end, end - QPointF(0, 4));
  p.drawText(bar.label, Qt::AlignHCenter, bar.text);
}

// The part of the line through C along D inside R (Liang-Barsky); false if it misses.
bool clipLine(const QRectF& r, QPointF c, glm::dvec2 d, QLineF& out) {
  double t0 = -1e18, t1 = 1e18;
  const double lo[2] = {r.left(), r.top()}, hi[2] = {r.right(), r.bottom()};
  const double at[2] = {c.x(), c.y()};
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(d[axis]) < 1e-12) {
      if (at[axis] < lo[axis] || at[axis] > hi[axis]) return false;
      continue;
    }
    double a = (lo[axis] - at[axis]) / d[axis], b = (hi[axis] - at[axis]) / d[axis];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  if (t0 > t1) return false;
  out = QLineF(c + QPointF(d.x, d.y) * t0, c + QPointF(d.x, d.y) * t1);
  return true;
}

}  // namespace

std::array<QPointF, 4> rotationHandles(const QFont& font, const QRect& r, QPointF centre,
                                       const std::array<glm::dvec2, 2>& traces) {
  const QRectF inner = crosshairBounds(font, r);
  const double distance = 0.35 * std::min(inner.width(), inner.height());
  std::array<QPointF, 4> h;
  for (size_t i = 0; i < 2; ++i) {
    const QPointF d(traces[i].x * distance, traces[i].y * distance);
    h[2 * i] = centre - d;
    h[2 * i + 1] = centre + d;
  }
  return h;
}

QRectF crosshairBounds(const QPainter& p, const QRect& r) { return crosshairBounds(p.font(), r); }

QRectF crosshairBounds(const QFont& font, const QRect& r) {
  QFont bold = font;
  bold.setBold(true);
  QFontMetrics fm(bold);
  const double gapX = kLetterMargin + fm.horizontalAdvance("W") + 4;  // widest letter
  const double gapY = kLetterMargin + fm.height() + 2;
  return QRectF(r).adjusted(gapX, gapY, -gapX, -gapY);
}

void drawSliceOverlay(QPainter& p, const SliceOverlay& o, const QRect& r,
                      const SliceToWidget& toWidget) {
  // The clip box first: the crosshair is what the user aims with, so it stays on top.
  if (o.showClip) {
    QPointF tl = toWidget(std::min(o.clipEdges[0].position, o.clipEdges[1].position),
                          std::min(o.clipEdges[2].position, o.clipEdges[3].position));
    QPointF br = toWidget(std::max(o.clipEdges[0].position, o.clipEdges[1].position),
                          std::max(o.clipEdges[2].position, o.clipEdges[3].position));
    p.setPen(QPen(clipBoxColor(), 2, o.clipActive ? Qt::SolidLine : Qt::DashLine));
    p.setBrush(Qt::NoBrush);
    p.drawRect(QRectF(tl, br));
  }

  // Crosshair lines in the colours of the two other views' planes, stopping short of the
  // band along each edge where the orientation letters sit.
  QRectF inner = crosshairBounds(p, r);
  QPointF c = toWidget(o.crosshair.x, o.crosshair.y);
  const QColor lineColor[2] = {planeColor(o.axes.uAxis), planeColor(o.axes.vAxis)};
  for (size_t i = 0; i < 2; ++i) {
    QLineF line;
    if (!clipLine(inner, c, o.traces[i], line)) continue;
    p.setPen(QPen(lineColor[i], 1));
    p.drawLine(line);
  }
  if (o.rotateHandles) {
    const auto handles = rotationHandles(p.font(), r, c, o.traces);
    for (size_t i = 0; i < handles.size(); ++i) {
      if (!inner.contains(handles[i])) continue;
      p.setPen(QPen(Qt::black, 1));
      p.setBrush(lineColor[i / 2]);
      p.drawEllipse(handles[i], kRotateHandleRadius, kRotateHandleRadius);
    }
    p.setBrush(Qt::NoBrush);
  }

  drawLabels(p, o.axes, r);
  p.setPen(QPen(planeColor(o.axes.nAxis), 2));
  p.drawRect(r.adjusted(0, 0, -1, -1));
  p.setPen(Qt::white);
  QRect text = r.adjusted(6, 4, -6, -4);
  QString slice = QString("%1 / %2").arg(o.slice + 1).arg(o.sliceCount);
  if (!o.planeNote.empty()) slice += "\n" + QString::fromStdString(o.planeNote);
  p.drawText(text, Qt::AlignLeft | Qt::AlignTop, slice);
  const int sliceLines = o.planeNote.empty() ? 1 : 2;
  drawCornerLines(p, o.studyLines, text.adjusted(0, sliceLines * p.fontMetrics().height(), 0, 0));
  p.drawText(text, Qt::AlignRight | Qt::AlignTop,
             QString::fromStdString(formatWindowLevel(o.wl, o.wlSource)));
  if (o.hasCursor)
    p.drawText(text, Qt::AlignLeft | Qt::AlignBottom, QString::fromStdString(o.cursorText));
  drawScaleBar(p, o.mmPerWidgetPixel, r);
}

}  // namespace voxray::ui
