#pragma once
// How text and arrow annotations (annotation_model.h) look over a slice view: an arrow's
// shaft with a filled head at its head point, and the text beside its point (an arrow's at its
// tail), with the dark halo the measurement labels have.
#include <functional>

#include <QColor>
#include <QPainter>

#include "annotation_model.h"
#include "slice_geometry.h"

namespace voxray::ui {

// The annotations' colour (selected: the measurements' selected yellow), clear of the
// measurements' cyan and of the crosshair's plane colours.
inline const QColor kAnnotationColor{255, 150, 40};
inline const QColor kAnnotationSelectedColor{255, 230, 60};

using MmToWidget = std::function<QPointF(const glm::dvec3& patientMm)>;

// The annotations of MODEL shown on this slice (AXES at SLICE of V).
void drawSliceAnnotations(QPainter& p, const QRectF& bounds, const Volume& v,
                          const AnnotationModel& model, const SliceAxes& axes, int slice,
                          const MmToWidget& toWidget);
// One arrow from TAIL to HEAD (widget pixels), as drawn for a finished one and while dragging.
void drawArrow(QPainter& p, QPointF head, QPointF tail, const QColor& color);

}  // namespace voxray::ui
