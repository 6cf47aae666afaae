#include "segment_scissors.h"

#include <algorithm>

#include "slice_geometry.h"
#include "voxray/io/error.h"

namespace voxray {

bool insidePolygon(const std::vector<glm::dvec2>& poly, glm::dvec2 p) {
  if (poly.size() < 3) return false;
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const glm::dvec2 a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

Mask scissorsKeep(const Segmentation& s, const Volume& v, const ViewProjection& proj,
                  const std::vector<glm::dvec2>& polygon, uint8_t label, ScissorsMode mode) {
  Mask keep = maskOf(s, label);
  const bool keepInside = mode == ScissorsMode::Keep;
  if (polygon.size() < 3) {
    if (keepInside) std::fill(keep.begin(), keep.end(), uint8_t(0));  // nothing is inside
    return keep;
  }
  glm::dvec2 lo = polygon.front(), hi = polygon.front();
  for (const glm::dvec2& q : polygon) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const glm::ivec3 d = s.grid.dims;
  for (int z = 0; z < d.z; ++z)
    for (int y = 0; y < d.y; ++y)
      for (int x = 0; x < d.x; ++x) {
        const size_t i = s.grid.index(x, y, z);
        if (!keep[i]) continue;
        const auto at = proj.project(voxelToWorldMm(v, glm::dvec3(x, y, z)));
        const bool inside = at && at->x >= lo.x && at->y >= lo.y && at->x <= hi.x &&
                            at->y <= hi.y && insidePolygon(polygon, *at);
        if (inside != keepInside) keep[i] = 0;
      }
  return keep;
}

void applyScissors(SegmentationModel& m, const Volume& v, const ViewProjection& proj,
                   const std::vector<glm::dvec2>& polygon, uint8_t label, ScissorsMode mode) {
  if (!m.active() || !m.segmentation().find(label))
    throw inputError("Choose a segment in the Segments panel first (or add one).");
  m.setMask(label, scissorsKeep(m.segmentation(), v, proj, polygon, label, mode),
            mode == ScissorsMode::Keep ? "Scissors keep" : "Scissors");
}

}  // namespace voxray
