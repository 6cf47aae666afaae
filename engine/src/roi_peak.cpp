#include "voxray/engine/roi_peak.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "peak_sphere.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

using peak::sphereWeights;
using peak::Weight;

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
