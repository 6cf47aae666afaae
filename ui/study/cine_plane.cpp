#include <algorithm>
#include <cmath>

#include "movie.h"
#include "voxray/io/volume.h"

namespace voxray {
namespace {

// D without its component along the unit vector N, normalised (or zero).
glm::dvec3 reject(const glm::dvec3& d, const glm::dvec3& n) {
  const glm::dvec3 r = d - glm::dot(d, n) * n;
  const double length = glm::length(r);
  return length > 1e-9 ? r / length : glm::dvec3(0.0);
}

}  // namespace

// The cine steps along the voxel axis closest to the view's normal, as the slice views do.
int cineSliceCount(const Volume& v, Orientation view) {
  return v.dims[sliceAxes(v.direction, view).nAxis];
}

PlaneGrid cinePlane(const Volume& v, Orientation view, int slice, glm::ivec2 size) {
  const int a = sliceAxes(v.direction, view).nAxis;
  const PatientAxes want = patientAxes(view);
  const glm::dvec3 normal = v.direction[a];
  PlaneGrid g;
  g.uDir = reject(want.right, normal);
  g.vDir = reject(reject(want.down, normal), g.uDir);
  if (g.uDir == glm::dvec3(0.0) || g.vDir == glm::dvec3(0.0)) {  // not an orthonormal frame
    g.uDir = v.direction[(a + 1) % 3];
    g.vDir = v.direction[(a + 2) % 3];
  }
  // The slice's rectangle: its centre, and its corners' reach along the screen axes.
  glm::dvec3 centreVoxel = (glm::dvec3(v.dims) - 1.0) * 0.5;
  centreVoxel[a] = slice;
  const glm::dvec3 centre = v.originMm + v.direction * (centreVoxel * v.spacingMm);
  glm::dvec2 half(0.0);
  double finest = 1e300;
  for (int b = 0; b < 3; ++b) {
    if (b == a) continue;
    const glm::dvec3 edge = v.direction[b] * (0.5 * v.dims[b] * v.spacingMm[b]);
    half += glm::dvec2(std::abs(glm::dot(edge, g.uDir)), std::abs(glm::dot(edge, g.vDir)));
    finest = std::min(finest, v.spacingMm[b]);
  }
  if (size.x <= 0 || size.y <= 0)
    size = glm::max(glm::ivec2(glm::round(2.0 * half / finest)), glm::ivec2(1));
  const double pixel = std::max(2.0 * half.x / size.x, 2.0 * half.y / size.y);
  g.size = size;
  g.spacingMm = glm::dvec2(pixel);
  g.originMm =
      centre - g.uDir * (pixel * (size.x - 1) * 0.5) - g.vDir * (pixel * (size.y - 1) * 0.5);
  return g;
}

}  // namespace voxray
