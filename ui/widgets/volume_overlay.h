#pragma once
// What the 3D view draws over the rendered image: the clip box with its face handles, the
// light handle, and the outlines of the three slice planes. Coordinates are the image's.
#include <string>
#include <vector>

#include <QPainter>

#include "crosshair_model.h"
#include "view_projection.h"
#include "voxray/engine/render_params.h"

namespace voxray::ui {

void drawClipBox(QPainter& p, const Volume& v, const ClipBox& box, const ViewProjection& view,
                 int activeFace);
void drawLightHandle(QPainter& p, const Volume& v, const RenderParams& params,
                     const ViewProjection& view, bool active);
// The three slice views' planes (turned ones too) where they cut the volume's box.
void drawCrosshairPlanes(QPainter& p, const Volume& v, const CrosshairModel& crosshair,
                         const ViewProjection& view);

// The patient axes (orientationMarker) as labelled arrows in the lower left corner of a view
// of SIZE pixels.
void drawOrientationMarker(QPainter& p, const ViewGeometry& g, QSizeF size);

// LINES top-left in R, one under the other (the patient and study text).
void drawCornerLines(QPainter& p, const std::vector<std::string>& lines, const QRect& r);

// The colours the slice views use for their frames, so the 3D planes can be matched.
QColor planeColor(int normalAxis);
// The clip box's edges and handles, in the 3D and slice views alike.
QColor clipBoxColor();

}  // namespace voxray::ui
