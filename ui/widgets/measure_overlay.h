#pragma once
// How measurements look over a slice view and the 3D view: lines, angle arms, ROI outlines,
// handles on their points, and each one's numbers beside it (measurementText).
#include <functional>

#include <QPainter>

#include "measurement_model.h"

namespace voxray::ui {

// Half the side of a handle square, and how near (widget pixels) a press grabs it.
constexpr double kHandleRadius = 4.0;
constexpr double kHandlePickPixels = 8.0;

using VoxelToWidget = std::function<QPointF(const glm::dvec3& voxel)>;

// The measurements shown whole on this slice, and 3D-picked points lying on it.
void drawSliceMeasurements(QPainter& p, const Volume& v, const MeasurementModel& m,
                           const SliceAxes& axes, int slice, const VoxelToWidget& toWidget);

// The 3D picks (distances with normal axis -1, and the pending first point) in the 3D view;
// TOWIDGET returns nothing for a point behind the eye.
using VoxelToScreen = std::function<std::optional<QPointF>(const glm::dvec3& voxel)>;
void drawPickedMeasurements(QPainter& p, const Volume& v, const MeasurementModel& m,
                            const VoxelToScreen& toWidget);

}  // namespace voxray::ui
