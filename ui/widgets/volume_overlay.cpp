#include "volume_overlay.h"

#include <algorithm>
#include <array>
#include <optional>

#include "clip_box_math.h"
#include "light_gizmo.h"
#include "mpr_planes.h"
#include "orientation_marker.h"
#include "slice_geometry.h"
#include "voxray/io/volume.h"

namespace voxray::ui {

namespace {

constexpr double kVolumeHandleRadius = 6.0;  // the 3D view's clip-face and light handles

std::optional<QPointF> screen(const ViewProjection& view, const glm::dvec3& world) {
  auto s = view.project(world);
  if (!s) return std::nullopt;
  return QPointF(s->x, s->y);
}

// Draws the 12 edges of the box [lo, hi] given in voxel coordinates.
void drawVoxelBox(QPainter& p, const Volume& v, const glm::dvec3& lo, const glm::dvec3& hi,
                  const ViewProjection& view) {
  std::array<std::optional<QPointF>, 8> corner;
  for (int c = 0; c < 8; ++c) {
    glm::dvec3 at((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
    corner[size_t(c)] = screen(view, voxelToWorldMm(v, at));
  }
  for (int c = 0; c < 8; ++c) {
    for (int bit : {1, 2, 4}) {
      int d = c | bit;
      if (d == c || !corner[size_t(c)] || !corner[size_t(d)]) continue;
      p.drawLine(*corner[size_t(c)], *corner[size_t(d)]);
    }
  }
}

}  // namespace

QColor planeColor(int normalAxis) {
  // Slicer's habit: axial red, sagittal yellow, coronal green (for LPS-aligned data).
  static const QColor colors[] = {QColor(230, 200, 40), QColor(60, 190, 60), QColor(220, 60, 60)};
  return colors[normalAxis % 3];
}

QColor clipBoxColor() {
  // Magenta: clear of the planes' red, green and yellow (its old orange was read as the
  // sagittal plane's yellow) and of the letters' light blue.
  return {235, 80, 235};
}

void drawClipBox(QPainter& p, const Volume& v, const ClipBox& box, const ViewProjection& view,
                 int activeFace) {
  QColor edge = clipBoxColor();
  edge.setAlpha(200);
  p.setPen(QPen(edge, 1.0));
  p.setBrush(Qt::NoBrush);
  drawVoxelBox(p, v, fractionToVoxel(v.dims, box.lo), fractionToVoxel(v.dims, box.hi), view);
  for (int face = 0; face < kFaceCount; ++face) {
    auto c = screen(view, clipFaceCentreWorld(v, box, face));
    if (!c) continue;
    bool active = face == activeFace;
    p.setPen(QPen(Qt::black, 1.0));
    p.setBrush(active ? QColor(255, 255, 255) : clipBoxColor());
    p.drawEllipse(*c, kVolumeHandleRadius, kVolumeHandleRadius);
  }
}

void drawLightHandle(QPainter& p, const Volume& v, const RenderParams& params,
                     const ViewProjection& view, bool active) {
  auto centre = screen(view, glm::dvec3(0.0));
  auto handle = screen(view, lightHandleWorld(v, params));
  if (!centre || !handle) return;
  p.setPen(QPen(QColor(255, 255, 160, 160), 1.0, Qt::DashLine));
  p.drawLine(*centre, *handle);
  p.setPen(QPen(Qt::black, 1.0));
  p.setBrush(active ? QColor(255, 255, 255) : QColor(255, 240, 120));
  p.drawEllipse(*handle, kVolumeHandleRadius + 3, kVolumeHandleRadius + 3);
  p.setPen(QPen(QColor(255, 240, 120), 1.5));
  for (int ray = 0; ray < 8; ++ray) {  // sun rays: this handle is the light
    QLineF l = QLineF::fromPolar(kVolumeHandleRadius + 9, ray * 45.0);
    QLineF inner = QLineF::fromPolar(kVolumeHandleRadius + 5, ray * 45.0);
    p.drawLine(*handle + inner.p2(), *handle + l.p2());
  }
}

void drawOrientationMarker(QPainter& p, const ViewGeometry& g, QSizeF size) {
  MarkerLayout layout;
  layout.armPx = std::clamp(std::min(size.width(), size.height()) * 0.06, 18.0, 40.0);
  layout.letterPx = std::max(16.0, double(p.fontMetrics().height()));
  const double arm = layout.armPx;
  const QPointF centre(arm + 14.0, size.height() - arm - 14.0);
  for (const MarkerAxis& a : orientationMarker(g, layout)) {
    // The slice planes' colours: the L-R axis is the sagittal plane's normal, and so on.
    const int axis = a.letter == 'L' || a.letter == 'R'   ? 0
                     : a.letter == 'P' || a.letter == 'A' ? 1
                                                          : 2;
    QColor c = planeColor(axis);
    if (a.towards < 0) c = c.darker(170);  // pointing away: behind the others
    const QPointF tip = centre + QPointF(a.tip.x, a.tip.y) * arm;
    p.setPen(QPen(c, 2.0));
    p.drawLine(centre, tip);
    if (a.labelAlpha <= 0.0) continue;  // end-on, or no room beside the longer arms' letters
    c.setAlphaF(float(a.labelAlpha));
    p.setPen(c);
    const QPointF label = centre + QPointF(a.label.x, a.label.y);
    const double half = 0.5 * layout.letterPx;
    p.drawText(QRectF(label.x() - half, label.y() - half, 2 * half, 2 * half), Qt::AlignCenter,
               QString(QChar(a.letter)));
  }
}

void drawCrosshairPlanes(QPainter& p, const Volume& v, const CrosshairModel& crosshair,
                         const ViewProjection& view) {
  p.setBrush(Qt::NoBrush);
  for (Orientation o : {Orientation::Axial, Orientation::Coronal, Orientation::Sagittal}) {
    const SliceAxes a = sliceAxes(v.direction, o);
    const auto polygon = planeInBox(v, crosshair.centre(), crosshair.frame(a).normal);
    p.setPen(QPen(planeColor(a.nAxis), 1.0));
    for (size_t i = 0; i < polygon.size(); ++i) {
      auto from = screen(view, voxelToWorldMm(v, polygon[i]));
      auto to = screen(view, voxelToWorldMm(v, polygon[(i + 1) % polygon.size()]));
      if (from && to) p.drawLine(*from, *to);
    }
  }
}

void drawCornerLines(QPainter& p, const std::vector<std::string>& lines, const QRect& r) {
  QString text;
  for (const auto& line : lines) text += QString::fromStdString(line) + "\n";
  p.save();
  p.setPen(Qt::white);
  p.drawText(r, Qt::AlignLeft | Qt::AlignTop, text.trimmed());
  p.restore();
}

}  // namespace voxray::ui
