#include "camera_control.h"

#include <algorithm>
#include <cmath>

namespace voxray {

const char* toString(StandardView v) {
  switch (v) {
    case StandardView::Anterior:
      return "Anterior";
    case StandardView::Posterior:
      return "Posterior";
    case StandardView::Left:
      return "Left";
    case StandardView::Right:
      return "Right";
    case StandardView::Superior:
      return "Superior";
    case StandardView::Inferior:
      return "Inferior";
  }
  return "?";
}

void orbit(CameraParams& c, double dx, double dy, double degreesPerPixel) {
  // The camera moves opposite to the mouse so the volume appears to follow it.
  c.azimuthDeg = std::remainder(c.azimuthDeg - dx * degreesPerPixel, 360.0);
  // The engine keeps the right vector horizontal, so elevation stops at the poles.
  c.elevationDeg = std::clamp(c.elevationDeg + dy * degreesPerPixel, -90.0, 90.0);
}

void zoomBy(CameraParams& c, double factor) { c.zoom = std::clamp(c.zoom * factor, 0.1, 20.0); }

void panBy(CameraParams& c, double dx, double dy, double mmPerPixel) {
  // panMm moves the look-at point; the volume moves the other way on screen.
  c.panMm.x -= dx * mmPerPixel;
  c.panMm.y += dy * mmPerPixel;
}

void setStandardView(CameraParams& c, StandardView v) {
  c.elevationDeg = 0.0;
  switch (v) {
    case StandardView::Anterior:
      c.azimuthDeg = 0.0;
      break;
    case StandardView::Posterior:
      c.azimuthDeg = 180.0;
      break;
    case StandardView::Left:  // from the patient's left (engine: azimuth 90)
      c.azimuthDeg = 90.0;
      break;
    case StandardView::Right:
      c.azimuthDeg = -90.0;
      break;
    case StandardView::Superior:
      c.azimuthDeg = 0.0;
      c.elevationDeg = 90.0;
      break;
    case StandardView::Inferior:
      c.azimuthDeg = 0.0;
      c.elevationDeg = -90.0;
      break;
  }
}

void resetCamera(CameraParams& c) {
  CameraParams fresh;
  fresh.projection = c.projection;
  fresh.fovDeg = c.fovDeg;
  c = fresh;
}

}  // namespace voxray
