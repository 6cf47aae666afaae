#include "voxray/io/segment_recipe.h"

#include <cmath>

#include "voxray/io/error.h"

namespace voxray {

Mask runRecipe(const Volume& v, const SegmentRecipe& r) {
  const VoxelGrid g = gridOf(v);
  Mask m = r.seed ? seededRegion(v, r.threshold, *r.seed, r.connectivity)
                  : thresholdMask(v, r.threshold);
  if (r.keepLargest) keepLargestIsland(g, m, r.connectivity);
  if (r.fillHoles) fillHoles(g, m);
  if (r.marginMm != 0.0) applyMargin(g, m, r.marginMm);
  if (r.smoothMm > 0.0) medianSmooth(g, m, r.smoothMm);
  return m;
}

glm::ivec3 seedFromMm(const Volume& v, glm::dvec3 lpsMm) {
  const glm::dvec3 ijk = gridOf(v).toIndex(lpsMm);
  const glm::dvec3 rounded = glm::round(ijk);
  if (!glm::all(glm::greaterThanEqual(rounded, glm::dvec3(0))) ||
      !glm::all(glm::lessThan(rounded, glm::dvec3(v.dims))))
    throw inputError("The seed at (" + std::to_string(lpsMm.x) + ", " + std::to_string(lpsMm.y) +
                     ", " + std::to_string(lpsMm.z) +
                     ") mm LPS is outside the volume: give a point inside it.");
  return glm::ivec3(rounded);
}

Segmentation segmentationFromRecipe(const Volume& v, const SegmentRecipe& r) {
  Segmentation s = emptySegmentation(v);
  Segment seg;
  seg.label = 1;
  seg.name = r.name;
  seg.colour = r.colour;
  s.segments.push_back(seg);
  setMask(s, 1, runRecipe(v, r));
  return s;
}

}  // namespace voxray
