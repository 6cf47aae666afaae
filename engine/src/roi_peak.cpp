#include "voxray/engine/roi_peak.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

// Sub-samples per axis of a cell the sphere's surface crosses: its fraction is then good to
// about 1e-3 of a cell, and the 1 cm³ sphere's summed weight to about 1e-3 relative (the
// tests measure it).
constexpr int kSubSamples = 16;

struct Weight {
  glm::ivec3 offset;
  double w;
};

// The sphere's voxel weights around a voxel centre: the fraction of each cell inside. The voxel
// axes are orthogonal (the direction is orthonormal), so an offset's length in mm is its
// index offset times the spacing, whatever the orientation: one kernel serves every centre.
std::vector<Weight> sphereWeights(const glm::dvec3& spacing, double r) {
  const glm::ivec3 reach = glm::ivec3(glm::ceil(r / spacing + 0.5));
  std::vector<Weight> out;
  for (int dk = -reach.z; dk <= reach.z; ++dk)
    for (int dj = -reach.y; dj <= reach.y; ++dj)
      for (int di = -reach.x; di <= reach.x; ++di) {
        const glm::dvec3 c = glm::dvec3(di, dj, dk) * spacing, h = 0.5 * spacing;
        // The cell's nearest and farthest points from the sphere's centre (an axis-aligned box).
        const glm::dvec3 near = glm::max(glm::abs(c) - h, glm::dvec3(0.0));
        const glm::dvec3 far = glm::abs(c) + h;
        if (glm::dot(near, near) >= r * r) continue;
        double w = 1.0;
        if (glm::dot(far, far) > r * r) {
          int in = 0;
          for (int z = 0; z < kSubSamples; ++z)
            for (int y = 0; y < kSubSamples; ++y)
              for (int x = 0; x < kSubSamples; ++x) {
                const glm::dvec3 p =
                    c - h + (glm::dvec3(x, y, z) + 0.5) / double(kSubSamples) * spacing;
                in += glm::dot(p, p) <= r * r;
              }
          w = double(in) / double(kSubSamples * kSubSamples * kSubSamples);
        }
        if (w > 0.0) out.push_back({{di, dj, dk}, w});
      }
  return out;
}

}  // namespace

RoiPeak roiPeak(const Volume& v, const PlaneRoi& roi, double radiusMm) {
  checkPlaneAxis(roi.normalAxis);
  if (!std::isfinite(radiusMm) || radiusMm <= 0.0)
    throw inputError("peak sphere radius " + std::to_string(radiusMm) +
                     " mm: give a positive number of mm");
  RoiPeak out;
  const std::vector<glm::ivec3> pixels = roiPixels(v, roi);
  if (pixels.empty()) return out;
  // The readout asks on every repaint: the last grid's kernel is kept (per thread).
  thread_local glm::dvec3 cachedSpacing(-1.0);
  thread_local double cachedRadius = -1.0;
  thread_local std::vector<Weight> kernel;
  if (cachedSpacing != v.spacingMm || cachedRadius != radiusMm) {
    kernel = sphereWeights(v.spacingMm, radiusMm);
    cachedSpacing = v.spacingMm;
    cachedRadius = radiusMm;
  }
  double sum = 0.0;
  glm::ivec3 lo(0), hi(0);
  for (const Weight& k : kernel) {
    sum += k.w;
    lo = glm::min(lo, k.offset);
    hi = glm::max(hi, k.offset);
  }
  out.sphereMm3 = sum * v.spacingMm.x * v.spacingMm.y * v.spacingMm.z;

  // The sphere's footprint in the ROI's plane: the in-plane offsets whose voxel centres lie
  // within the radius. Each must land on a pixel of the ROI (the prism rule in roi_peak.h).
  const int n = roi.normalAxis;
  std::vector<glm::ivec3> footprint;
  for (const Weight& k : kernel)
    if (k.offset[n] == 0 &&
        glm::length(glm::dvec3(k.offset) * v.spacingMm) <= radiusMm * (1.0 + 1e-12))
      footprint.push_back(k.offset);
  auto key = [](const glm::ivec3& p) { return std::make_tuple(p.x, p.y, p.z); };
  std::set<std::tuple<int, int, int>> inRoi;
  for (const glm::ivec3& p : pixels) inRoi.insert(key(p));

  for (const glm::ivec3& c : pixels) {
    if (glm::any(glm::lessThan(c + lo, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(c + hi, v.dims)))
      continue;  // the sphere would reach outside the volume
    if (!std::all_of(footprint.begin(), footprint.end(),
                     [&](const glm::ivec3& o) { return inRoi.count(key(c + o)) > 0; }))
      continue;
    double acc = 0.0;
    for (const Weight& k : kernel) {
      const glm::ivec3 p = c + k.offset;
      acc += k.w * double(v.at(p.x, p.y, p.z));
    }
    // The stored values' weighted mean, then the linear rescale: the same as averaging
    // physical values.
    const double mean = v.toPhysical(acc / sum);
    ++out.centres;
    if (!out.mean || mean > *out.mean) {
      out.mean = mean;
      out.centre = c;
    }
  }
  return out;
}

}  // namespace voxray
