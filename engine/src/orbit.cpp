#include "voxray/engine/orbit.h"

namespace voxray {

void orbitCamera(CameraParams& c, Orbit orbit, int frame, int frames) {
  const double angle = 360.0 * frame / frames;
  if (orbit == Orbit::Azimuth) {
    c.azimuthDeg = angle;
    return;
  }
  c.azimuthDeg = 90.0;
  c.elevationDeg = angle - 90.0;
}

}  // namespace voxray
