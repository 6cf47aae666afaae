#include "slice_clip.h"

#include "clip_box_math.h"

namespace voxray {

namespace {

// Slice coordinate of a box fraction along a screen axis of N voxels.
double toScreen(double fraction, bool flip, int n) {
  return (flip ? 1.0 - fraction : fraction) * n;
}
double toFraction(double position, bool flip, int n) {
  double f = position / n;
  return flip ? 1.0 - f : f;
}

}  // namespace

std::array<SliceClipEdge, 4> sliceClipEdges(const SliceAxes& a, const glm::ivec3& dims,
                                            const ClipBox& box) {
  int nu = dims[a.uAxis], nv = dims[a.vAxis];
  return {{
      {2 * a.uAxis, true, toScreen(box.lo[a.uAxis], a.uFlip, nu)},
      {2 * a.uAxis + 1, true, toScreen(box.hi[a.uAxis], a.uFlip, nu)},
      {2 * a.vAxis, false, toScreen(box.lo[a.vAxis], a.vFlip, nv)},
      {2 * a.vAxis + 1, false, toScreen(box.hi[a.vAxis], a.vFlip, nv)},
  }};
}

void dragSliceClipEdge(ClipBox& box, const SliceAxes& a, const glm::ivec3& dims, int face,
                       double position) {
  int axis = faceAxis(face);
  bool flip = axis == a.uAxis ? a.uFlip : a.vFlip;
  setClipFace(box, face, toFraction(position, flip, dims[axis]));
}

bool sliceInsideClip(const SliceAxes& a, const glm::ivec3& dims, const ClipBox& box, int slice) {
  double f = voxelToFraction(dims[a.nAxis], slice);
  return f >= box.lo[a.nAxis] && f <= box.hi[a.nAxis];
}

}  // namespace voxray
