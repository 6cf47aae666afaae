#include "voxray/engine/mask_peak.h"

#include <cmath>
#include <string>

#include "peak_sphere.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

RoiPeak maskPeak(const Volume& v, const std::vector<uint8_t>& labels, uint8_t label,
                 double radiusMm) {
  if (labels.size() != v.voxelCount())
    throw inputError("segment peak: the label map has " + std::to_string(labels.size()) +
                     " voxels, the volume " + std::to_string(v.voxelCount()) +
                     "; give a segmentation made on this volume's grid");
  if (!std::isfinite(radiusMm) || radiusMm <= 0.0)
    throw inputError("peak sphere radius " + std::to_string(radiusMm) +
                     " mm: give a positive number of mm");
  RoiPeak out;
  const std::vector<peak::Weight> kernel = peak::sphereWeights(v.spacingMm, radiusMm);
  double sum = 0.0;
  glm::ivec3 lo(0), hi(0);
  for (const peak::Weight& k : kernel) {
    sum += k.w;
    lo = glm::min(lo, k.offset);
    hi = glm::max(hi, k.offset);
  }
  out.sphereMm3 = sum * v.spacingMm.x * v.spacingMm.y * v.spacingMm.z;
  // The voxels whose centres lie within the radius: each must be in the region.
  std::vector<long> footprint;
  const long sx = 1, sy = v.dims.x, sz = long(v.dims.x) * v.dims.y;
  for (const peak::Weight& k : kernel)
    if (glm::length(glm::dvec3(k.offset) * v.spacingMm) <= radiusMm * (1.0 + 1e-12))
      footprint.push_back(k.offset.x * sx + k.offset.y * sy + k.offset.z * sz);
  std::vector<long> offsets;
  for (const peak::Weight& k : kernel)
    offsets.push_back(k.offset.x * sx + k.offset.y * sy + k.offset.z * sz);
  // Every centre of the region in turn: a segment of a PET (voxels of 2 to 4 mm) has some
  // thousands of voxels and the kernel some hundreds, milliseconds in all.
  for (int k = -lo.z; k < v.dims.z - hi.z; ++k)
    for (int j = -lo.y; j < v.dims.y - hi.y; ++j)
      for (int i = -lo.x; i < v.dims.x - hi.x; ++i) {
        const long c = long(v.index(i, j, k));
        if (labels[size_t(c)] != label) continue;
        bool fits = true;
        for (long o : footprint)
          if (labels[size_t(c + o)] != label) {
            fits = false;
            break;
          }
        if (!fits) continue;
        double acc = 0.0;
        for (size_t n = 0; n < kernel.size(); ++n)
          acc += kernel[n].w * double(v.voxels[size_t(c + offsets[n])]);
        // The stored values' weighted mean, then the linear rescale (as roiPeak).
        const double mean = v.toPhysical(acc / sum);
        ++out.centres;
        if (!out.mean || mean > *out.mean) {
          out.mean = mean;
          out.centre = {i, j, k};
        }
      }
  return out;
}

std::vector<uint8_t> maskOnGrid(const VoxelGrid& from, const std::vector<uint8_t>& labels,
                                uint8_t label, const Volume& onto) {
  if (labels.size() != from.voxelCount())
    throw inputError("segment on another grid: the label map has " + std::to_string(labels.size()) +
                     " voxels, its volume " + std::to_string(from.voxelCount()));
  std::vector<uint8_t> out(onto.voxelCount(), 0);
  for (int k = 0; k < onto.dims.z; ++k)
    for (int j = 0; j < onto.dims.y; ++j)
      for (int i = 0; i < onto.dims.x; ++i) {
        const glm::dvec3 p =
            onto.originMm + onto.direction * (onto.spacingMm * glm::dvec3(i, j, k));
        const glm::ivec3 n(glm::round(from.toIndex(p)));
        if (glm::any(glm::lessThan(n, glm::ivec3(0))) ||
            glm::any(glm::greaterThanEqual(n, from.dims)))
          continue;
        out[onto.index(i, j, k)] = labels[from.index(n.x, n.y, n.z)] == label ? 1 : 0;
      }
  return out;
}

}  // namespace voxray
