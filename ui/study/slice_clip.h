#pragma once
// The clip box as seen in a slice view: two vertical and two horizontal edges that the
// user drags. Coordinates are slice-pixel units (see slice_geometry.h).
#include <array>

#include "no_qt.h"
#include "slice_geometry.h"
#include "voxray/engine/render_params.h"

namespace voxray {

struct SliceClipEdge {
  int face;       // clip_box_math.h's face number
  bool vertical;  // true: a vertical line at u = position; false: horizontal at v
  double position;
};

// Left/right edges (along u) then top/bottom edges (along v) of BOX in this view.
std::array<SliceClipEdge, 4> sliceClipEdges(const SliceAxes& a, const glm::ivec3& dims,
                                            const ClipBox& box);
// Moves FACE so that its edge lies at slice coordinate POSITION (u or v as the edge is).
void dragSliceClipEdge(ClipBox& box, const SliceAxes& a, const glm::ivec3& dims, int face,
                       double position);
// Whether the slice with index SLICE lies inside the box across the view's normal.
bool sliceInsideClip(const SliceAxes& a, const glm::ivec3& dims, const ClipBox& box, int slice);

}  // namespace voxray
