#pragma once
// Mouse and keyboard camera control for the 3D view, as pure functions on CameraParams
// (3D Slicer's habits: left-drag rotates, wheel/right-drag zooms, middle or Shift+left pans).
#include "no_qt.h"
#include "voxray/engine/render_params.h"

namespace voxray {

enum class StandardView { Anterior, Posterior, Left, Right, Superior, Inferior };
const char* toString(StandardView v);

// Dragging by (dx, dy) pixels turns the volume with the mouse: right turns it to the right.
void orbit(CameraParams& c, double dxPixels, double dyPixels, double degreesPerPixel = 0.4);
// factor > 1 zooms in; the zoom stays within [0.1, 20].
void zoomBy(CameraParams& c, double factor);
// Moves the volume with the mouse; MM_PER_PIXEL: the view's scale at the volume centre.
void panBy(CameraParams& c, double dxPixels, double dyPixels, double mmPerPixel);
void setStandardView(CameraParams& c, StandardView v);
void resetCamera(CameraParams& c);  // the anterior view, zoom 1, no pan

}  // namespace voxray
