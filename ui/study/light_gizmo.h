#pragma once
// The light as a handle on a sphere around the volume: the user drags it over the 3D view
// and the point light moves with it, whether the light follows the camera (position in the
// camera's frame) or stays fixed in patient space (LPS mm).
#include <array>
#include <string>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "view_projection.h"
#include "voxray/engine/render_params.h"

namespace voxray {

// Radius of the gizmo's sphere in units of the volume's bounding radius.
constexpr double kGizmoRadius = 1.3;

// World position (mm from the volume centre) of the light for these parameters.
glm::dvec3 lightWorld(const Volume& v, const RenderParams& p);
// Where the handle is drawn: the light's direction from the centre, on the gizmo sphere.
glm::dvec3 lightHandleWorld(const Volume& v, const RenderParams& p);

// A drag to SCREEN: the point under the mouse on the gizmo sphere's front (outside the
// sphere's outline: on the outline) becomes the light direction. Returns the light with
// position set in the frame light.followCamera asks for.
LightParams lightFromScreen(const Volume& v, const RenderParams& p, const ViewProjection& view,
                            const glm::dvec2& screen);

// How the panel names the light position's three numbers: in patient space they are mm
// from the volume centre along L, P, S; following the camera they are multiples of the
// volume's bounding radius from the eye, to the right, up and back towards the viewer.
struct LightPositionUnit {
  std::array<std::string, 3> axes;  // "L (x)" ...
  std::string suffix;               // " mm" or " × radius"
  std::string tooltip;
};
LightPositionUnit lightPositionUnit(bool followCamera);

// Converts a light between camera-following and fixed without moving it this frame.
LightParams withFollowCamera(const Volume& v, const RenderParams& p, bool follow);

}  // namespace voxray
