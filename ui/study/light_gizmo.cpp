#include "light_gizmo.h"

#include <cmath>

#include "voxray/io/volume.h"

namespace voxray {

namespace {

double volumeRadius(const Volume& v) { return 0.5 * glm::length(v.extentMm()); }

// The inverse of camera.cpp's followCamera mapping.
glm::dvec3 worldToCameraFrame(const ViewGeometry& g, const glm::dvec3& world, double radius) {
  glm::dvec3 rel = world - g.eye;
  return glm::dvec3(glm::dot(rel, g.right), glm::dot(rel, g.up), -glm::dot(rel, g.forward)) /
         radius;
}

LightParams placeLight(const Volume& v, const RenderParams& p, const glm::dvec3& world) {
  LightParams l = p.light;
  l.position =
      l.followCamera ? worldToCameraFrame(makeViewGeometry(v, p), world, volumeRadius(v)) : world;
  return l;
}

}  // namespace

glm::dvec3 lightWorld(const Volume& v, const RenderParams& p) {
  return makeViewGeometry(v, p).lightWorld;
}

glm::dvec3 lightHandleWorld(const Volume& v, const RenderParams& p) {
  glm::dvec3 w = lightWorld(v, p);
  double len = glm::length(w);
  glm::dvec3 dir = len > 1e-9 ? w / len : -makeViewGeometry(v, p).forward;
  return dir * (kGizmoRadius * volumeRadius(v));
}

LightParams lightFromScreen(const Volume& v, const RenderParams& p, const ViewProjection& view,
                            const glm::dvec2& screen) {
  const ViewGeometry& g = view.g;
  double sphereMm = kGizmoRadius * volumeRadius(v);
  // The ray under the mouse (continuous pixel coordinates, as ViewGeometry::ray).
  double sx = (2.0 * screen.x / view.size.x - 1.0) * g.halfHeight * g.aspect;
  double sy = (1.0 - 2.0 * screen.y / view.size.y) * g.halfHeight;
  glm::dvec3 origin = g.orthographic ? g.eye + g.right * sx + g.up * sy : g.eye;
  glm::dvec3 dir =
      g.orthographic ? g.forward : glm::normalize(g.forward + g.right * sx + g.up * sy);
  // Its first hit on the gizmo sphere; a ray that misses takes the nearest point of the
  // sphere's outline, so the handle follows the mouse around the rim.
  double tClosest = -glm::dot(origin, dir);
  glm::dvec3 closest = origin + dir * tClosest;
  double d2 = glm::dot(closest, closest), r2 = sphereMm * sphereMm;
  glm::dvec3 onSphere = d2 < r2 ? origin + dir * (tClosest - std::sqrt(r2 - d2))
                                : closest * (sphereMm / std::max(std::sqrt(d2), 1e-9));
  // The light sits beyond the handle, along the same direction, outside the volume.
  return placeLight(v, p, onSphere * 2.0);
}

LightParams withFollowCamera(const Volume& v, const RenderParams& p, bool follow) {
  glm::dvec3 world = lightWorld(v, p);
  RenderParams q = p;
  q.light.followCamera = follow;
  return placeLight(v, q, world);
}

LightPositionUnit lightPositionUnit(bool followCamera) {
  if (followCamera)
    return {{"Right", "Up", "Back"},
            " \u00d7 radius",
            "Multiples of the volume's bounding radius from the eye: to the right, up, and back "
            "towards the viewer (negative: in front of the eye)"};
  return {{"L (x)", "P (y)", "S (z)"},
          " mm",
          "Millimetres from the volume centre towards the patient's left, posterior and "
          "superior (negative: right, anterior, inferior)"};
}

}  // namespace voxray
