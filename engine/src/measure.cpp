#include "voxray/engine/measure.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {
constexpr double kInsideTolerance = 1e-9;  // boundary pixels count, despite rounding
}  // namespace

glm::dvec3 voxelToPatient(const Volume& v, const glm::dvec3& voxel) {
  return v.originMm + v.direction * (voxel * v.spacingMm);
}

glm::dvec3 patientToVoxel(const Volume& v, const glm::dvec3& patientMm) {
  // The direction is orthonormal: its transpose is its inverse.
  return (glm::transpose(v.direction) * (patientMm - v.originMm)) / v.spacingMm;
}

bool insideVolume(const Volume& v, const glm::dvec3& voxel) {
  return glm::all(glm::greaterThanEqual(voxel, glm::dvec3(-0.5))) &&
         glm::all(glm::lessThanEqual(voxel, glm::dvec3(v.dims) - 0.5));
}

double distanceMm(const Volume& v, const glm::dvec3& a, const glm::dvec3& b) {
  return glm::length(voxelToPatient(v, b) - voxelToPatient(v, a));
}

std::optional<double> angleDeg(const Volume& v, const glm::dvec3& a, const glm::dvec3& vertex,
                               const glm::dvec3& c) {
  const glm::dvec3 o = voxelToPatient(v, vertex);
  const glm::dvec3 p = voxelToPatient(v, a) - o, q = voxelToPatient(v, c) - o;
  const double lp = glm::length(p), lq = glm::length(q);
  if (lp <= 0.0 || lq <= 0.0) return std::nullopt;
  // atan2 of |p x q| and p . q keeps its precision near 0 and 180 degrees, where acos does not.
  return glm::degrees(std::atan2(glm::length(glm::cross(p, q)), glm::dot(p, q)));
}

void checkPlaneAxis(int axis) {
  if (axis < 0 || axis > 2)
    throw inputError("measurement plane axis " + std::to_string(axis) +
                     " is not a volume axis: use 0 (i), 1 (j) or 2 (k)");
}

namespace {

// The shape's area in mm² and its voxels (the pixel rule in measure.h).
double roiPixelsAndArea(const Volume& v, const PlaneRoi& roi, std::vector<glm::ivec3>* pixels) {
  checkPlaneAxis(roi.normalAxis);
  const int n = roi.normalAxis, ua = (n + 1) % 3, va = (n + 2) % 3;
  // In-plane extents in mm (the voxel axes are orthogonal: mm = voxels * spacing).
  const glm::dvec2 a(roi.a[ua], roi.a[va]), b(roi.b[ua], roi.b[va]);
  const glm::dvec2 spacing(v.spacingMm[ua], v.spacingMm[va]);
  const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
  const glm::dvec2 sizeMm = (hi - lo) * spacing;
  const double area = roi.shape == RoiShape::Rect ? sizeMm.x * sizeMm.y
                                                  : std::numbers::pi * sizeMm.x * sizeMm.y / 4;
  const double slice = std::round(roi.a[n]);
  if (area <= 0.0 || v.voxelCount() == 0 || slice < 0 || slice >= v.dims[n]) return area;

  const glm::dvec2 centre = (lo + hi) * 0.5, radius = (hi - lo) * 0.5;
  auto inside = [&](double x, double y) {
    if (roi.shape == RoiShape::Rect)
      return x >= lo.x - kInsideTolerance && x <= hi.x + kInsideTolerance &&
             y >= lo.y - kInsideTolerance && y <= hi.y + kInsideTolerance;
    const double dx = (x - centre.x) / radius.x, dy = (y - centre.y) / radius.y;
    return dx * dx + dy * dy <= 1.0 + kInsideTolerance;
  };
  // The pixel range, clamped in floating point first: a far corner must not overflow an int.
  const glm::dvec2 first = glm::clamp(glm::ceil(lo - kInsideTolerance), glm::dvec2(0.0),
                                      glm::dvec2(v.dims[ua], v.dims[va]));
  const glm::dvec2 last = glm::clamp(glm::floor(hi + kInsideTolerance), glm::dvec2(-1.0),
                                     glm::dvec2(v.dims[ua] - 1, v.dims[va] - 1));
  const int x0 = int(first.x), x1 = int(last.x), y0 = int(first.y), y1 = int(last.y);
  glm::ivec3 idx(0);
  idx[n] = int(slice);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      if (!inside(x, y)) continue;
      idx[ua] = x;
      idx[va] = y;
      pixels->push_back(idx);
    }
  return area;
}

}  // namespace

std::vector<glm::ivec3> roiPixels(const Volume& v, const PlaneRoi& roi) {
  std::vector<glm::ivec3> pixels;
  roiPixelsAndArea(v, roi, &pixels);
  return pixels;
}

RoiStats roiStats(const Volume& v, const PlaneRoi& roi) {
  RoiStats s;
  std::vector<glm::ivec3> pixels;
  s.areaMm2 = roiPixelsAndArea(v, roi, &pixels);
  // Welford's running mean and variance: stable for thousands of similar values.
  double mean = 0.0, m2 = 0.0, mn = 0.0, mx = 0.0;
  for (const glm::ivec3& idx : pixels) {
    const double value = v.toPhysical(v.at(idx.x, idx.y, idx.z));
    ++s.pixels;
    const double delta = value - mean;
    mean += delta / double(s.pixels);
    m2 += delta * (value - mean);
    mn = s.pixels == 1 ? value : std::min(mn, value);
    mx = s.pixels == 1 ? value : std::max(mx, value);
  }
  if (s.pixels == 0) return s;
  s.mean = mean;
  s.min = mn;
  s.max = mx;
  if (s.pixels > 1) s.sd = std::sqrt(m2 / double(s.pixels - 1));
  return s;
}

}  // namespace voxray
