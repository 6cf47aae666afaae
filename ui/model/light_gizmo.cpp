#include "light_gizmo.h"

#include <cmath>

#include "voxray/io/volume.h"

namespace voxray::ui {

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
  l.position = l.followCamera ? worldToCameraFrame(makeViewGeometry(v, p), world, volumeRadius(v))
                              : world;
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
  // Screen offset from the projected centre, in mm at the centre's depth.
  auto centre = view.project(glm::dvec3(0.0));
  if (!centre) return p.light;
  glm::dvec2 offset = (screen - *centre) * view.mmPerPixel();
  double x = offset.x / sphereMm, y = -offset.y / sphereMm;
  double r2 = x * x + y * y;
  if (r2 > 1.0) {
    x /= std::sqrt(r2);
    y /= std::sqrt(r2);
    r2 = 1.0;
  }
  double z = std::sqrt(1.0 - r2);  // towards the viewer: the lit side faces the user
  glm::dvec3 dir = g.right * x + g.up * y - g.forward * z;
  // The light sits a little beyond the handle so that it stays outside the volume.
  return placeLight(v, p, dir * (2.0 * sphereMm));
}

LightParams withFollowCamera(const Volume& v, const RenderParams& p, bool follow) {
  glm::dvec3 world = lightWorld(v, p);
  RenderParams q = p;
  q.light.followCamera = follow;
  return placeLight(v, q, world);
}

}  // namespace voxray::ui
