#pragma once
// How measurements look over a slice view and the 3D view: lines, angle arms, ROI outlines,
// handles on their points, and each one's numbers beside it (measurementText).
#include <functional>

#include <QFontMetricsF>
#include <QPainter>
#include <QStringList>

#include "measurement_model.h"

namespace voxray::ui {

// Half the side of a handle square, and how near (widget pixels) a press grabs it.
constexpr double kHandleRadius = 4.0;
constexpr double kHandlePickPixels = 8.0;

using VoxelToWidget = std::function<QPointF(const glm::dvec3& voxel)>;

// A measurement's numbers as drawn: beside AT (right of it and above, else left of it),
// broken at the text's ", " and double-space separators into lines no wider than BOUNDS
// where it must be, and moved inside BOUNDS (the view), so that no number runs off it.
struct MeasureLabel {
  QStringList lines;
  QRectF rect;  // the lines' box; the first baseline is rect.top() + the font's ascent
};
MeasureLabel layoutMeasureLabel(const QFontMetricsF& fm, const QRectF& bounds, QPointF at,
                                const QString& text);

// The measurements shown whole on this slice, and 3D-picked points lying on it; their
// labels stay inside BOUNDS.
void drawSliceMeasurements(QPainter& p, const QRectF& bounds, const Volume& v,
                           const MeasurementModel& m, const SliceAxes& axes, int slice,
                           const VoxelToWidget& toWidget);

// The 3D picks (distances with normal axis -1, and the pending first point) in the 3D view;
// TOWIDGET returns nothing for a point behind the eye.
using VoxelToScreen = std::function<std::optional<QPointF>(const glm::dvec3& voxel)>;
void drawPickedMeasurements(QPainter& p, const QRectF& bounds, const Volume& v,
                            const MeasurementModel& m, const VoxelToScreen& toWidget);

}  // namespace voxray::ui
