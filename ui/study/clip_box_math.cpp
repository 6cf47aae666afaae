#include "clip_box_math.h"

#include <algorithm>
#include <cmath>

#include "slice_geometry.h"
#include "voxray/io/orientation.h"
#include "voxray/io/volume.h"

namespace voxray {

void setClipFace(ClipBox& box, int face, double fraction) {
  int a = faceAxis(face);
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (faceIsHigh(face)) {
    box.hi[a] = std::max(fraction, box.lo[a] + kMinClipGap);
  } else {
    box.lo[a] = std::min(fraction, box.hi[a] - kMinClipGap);
  }
}

double clipFace(const ClipBox& box, int face) {
  return faceIsHigh(face) ? box.hi[faceAxis(face)] : box.lo[faceAxis(face)];
}

std::array<std::string, 3> clipAxisLabels(const glm::dmat3& direction) {
  // The low face lies where the index axis points away from: the reversed axes' letters.
  std::string to = axesCodeFromDirection(direction), from = axesCodeFromDirection(-direction);
  std::array<std::string, 3> out;
  for (size_t a = 0; a < 3; ++a) out[a] = std::string(1, from[a]) + "\u2013" + to[a];
  return out;
}

glm::dvec3 fractionToVoxel(const glm::ivec3& dims, const glm::dvec3& fraction) {
  return -0.5 + fraction * glm::dvec3(dims);  // the engine's convention (camera.cpp)
}

double voxelToFraction(int dims, double voxel) { return (voxel + 0.5) / double(dims); }

glm::dvec3 clipFaceCentreWorld(const Volume& v, const ClipBox& box, int face) {
  glm::dvec3 f = 0.5 * (box.lo + box.hi);
  f[faceAxis(face)] = clipFace(box, face);
  return voxelToWorldMm(v, fractionToVoxel(v.dims, f));
}

namespace {

// Screen direction (pixels per unit fraction) in which FACE moves, or nullopt.
std::optional<glm::dvec2> faceScreenAxis(const Volume& v, const ClipBox& box,
                                         const ViewProjection& view, int face) {
  constexpr double kProbe = 0.01;
  ClipBox moved = box;
  moved.lo[faceAxis(face)] = 0.0;  // probe without the gap clamp getting in the way
  moved.hi[faceAxis(face)] = 1.0;
  glm::dvec3 at = clipFaceCentreWorld(v, box, face);
  glm::dvec3 f = 0.5 * (box.lo + box.hi);
  f[faceAxis(face)] = clipFace(box, face) + kProbe;
  glm::dvec3 next = voxelToWorldMm(v, fractionToVoxel(v.dims, f));
  auto a = view.project(at), b = view.project(next);
  if (!a || !b) return std::nullopt;
  return (*b - *a) / kProbe;
}

}  // namespace

std::optional<int> pickClipFace(const Volume& v, const ClipBox& box, const ViewProjection& view,
                                const glm::dvec2& screen, double maxPixels) {
  std::optional<int> best;
  double bestDist = maxPixels;
  for (int face = 0; face < kFaceCount; ++face) {
    auto p = view.project(clipFaceCentreWorld(v, box, face));
    auto axis = faceScreenAxis(v, box, view, face);
    // A face seen edge-on cannot be dragged meaningfully along its normal.
    if (!p || !axis || glm::length(*axis) < 20.0) continue;
    double d = glm::distance(*p, screen);
    if (d <= bestDist) {
      bestDist = d;
      best = face;
    }
  }
  return best;
}

ClipBox dragClipFace(const Volume& v, const ClipBox& start, const ViewProjection& view, int face,
                     const glm::dvec2& screenDelta) {
  ClipBox box = start;
  auto axis = faceScreenAxis(v, start, view, face);
  if (!axis) return box;
  double len2 = glm::dot(*axis, *axis);
  if (len2 < 1e-9) return box;
  setClipFace(box, face, clipFace(start, face) + glm::dot(screenDelta, *axis) / len2);
  return box;
}

}  // namespace voxray
