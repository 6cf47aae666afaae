#pragma once
// Where world points land on the 3D view's screen, and back: the geometry the clip-box
// handles, the light gizmo and panning need. Built on the engine's own makeViewGeometry
// so overlays line up with the rendered pixels.
#include <optional>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "voxray/engine/camera.h"

namespace voxray {

struct ViewProjection {
  ViewGeometry g;
  glm::dvec2 size{1.0};  // view size in pixels (any resolution: the image is scaled to it)

  // Screen pixel of a world point; nullopt behind the eye.
  std::optional<glm::dvec2> project(const glm::dvec3& world) const;
  // Millimetres per screen pixel in the plane through the volume centre.
  double mmPerPixel() const;
};

ViewProjection makeViewProjection(const Volume& v, const RenderParams& p, glm::dvec2 viewSize);

}  // namespace voxray
