#include "voxray/engine/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "voxray/io/volume.h"

namespace voxray {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kFrameMargin = 1.05;  // leaves a thin border around the framed volume
}  // namespace

ViewGeometry makeViewGeometry(const Volume& v, const RenderParams& p) {
  ViewGeometry g;
  const CameraParams& c = p.camera;
  glm::dmat3 voxelToWorld =
      v.direction * glm::dmat3(glm::dvec3(v.spacingMm.x, 0, 0), glm::dvec3(0, v.spacingMm.y, 0),
                               glm::dvec3(0, 0, v.spacingMm.z));
  g.worldToVoxel = glm::inverse(voxelToWorld);
  g.voxelCentre = (glm::dvec3(v.dims) - 1.0) * 0.5;
  g.gradToWorld = glm::transpose(g.worldToVoxel);

  double az = c.azimuthDeg * kDeg, el = c.elevationDeg * kDeg;
  // Azimuth 0 looks from anterior (-y in LPS) with superior up; the right vector stays
  // horizontal, so looking straight down (elevation 90) is not a degenerate case.
  g.forward = glm::dvec3(-std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), -std::sin(el));
  g.right = glm::dvec3(std::cos(az), std::sin(az), 0.0);
  g.up = glm::cross(g.right, g.forward);

  double radius = 0.5 * glm::length(v.extentMm());
  g.orthographic = c.projection == Projection::Orthographic;
  g.aspect = p.height > 0 ? double(p.width) / double(p.height) : 1.0;
  double halfFov = 0.5 * c.fovDeg * kDeg;
  double distance = c.distanceMm > 0.0 ? c.distanceMm : kFrameMargin * radius / std::sin(halfFov);
  if (g.orthographic) {
    g.halfHeight = kFrameMargin * radius / c.zoom;
    if (c.distanceMm <= 0.0) distance = 2.0 * radius + 1.0;
  } else {
    g.halfHeight = std::tan(halfFov) / c.zoom;
  }
  glm::dvec3 target = g.right * c.panMm.x + g.up * c.panMm.y;
  g.eye = target - g.forward * distance;

  g.clipLo = -0.5 + p.clip.lo * glm::dvec3(v.dims);
  g.clipHi = -0.5 + p.clip.hi * glm::dvec3(v.dims);

  const LightParams& l = p.light;
  g.lightWorld = l.followCamera ? g.eye + radius * (g.right * l.position.x + g.up * l.position.y -
                                                    g.forward * l.position.z)
                                : l.position;
  return g;
}

void ViewGeometry::ray(int px, int py, int width, int height, glm::dvec3& originWorld,
                       glm::dvec3& dirWorld) const {
  double sx = (2.0 * (px + 0.5) / width - 1.0) * halfHeight * aspect;
  double sy = (1.0 - 2.0 * (py + 0.5) / height) * halfHeight;
  if (orthographic) {
    originWorld = eye + right * sx + up * sy;
    dirWorld = forward;
  } else {
    originWorld = eye;
    dirWorld = glm::normalize(forward + right * sx + up * sy);
  }
}

bool intersectBox(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& lo,
                  const glm::dvec3& hi, double& tEnter, double& tExit, int& enterAxis) {
  double t0 = -std::numeric_limits<double>::infinity();
  double t1 = std::numeric_limits<double>::infinity();
  enterAxis = -1;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      // Parallel to this slab: inside it everywhere or nowhere. A ray in a face's plane is
      // inside, within the kernel's margin (kernels/intersection/intersect.cl), so float and double
      // agree.
      double margin = 1e-5 * (1.0 + std::abs(lo[a]) + std::abs(hi[a]));
      if (o[a] < lo[a] - margin || o[a] > hi[a] + margin) return false;
      continue;
    }
    double inv = 1.0 / d[a];
    double ta = (lo[a] - o[a]) * inv, tb = (hi[a] - o[a]) * inv;
    if (ta > tb) std::swap(ta, tb);
    if (ta > t0) {
      t0 = ta;
      enterAxis = a;
    }
    t1 = std::min(t1, tb);
  }
  if (t0 < 0.0) {
    t0 = 0.0;  // the eye is inside the box
    enterAxis = -1;
  }
  tEnter = t0;
  tExit = t1;
  return t1 >= t0;
}

}  // namespace voxray
