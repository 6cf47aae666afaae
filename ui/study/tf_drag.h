#pragma once
// Shaping the transfer function by dragging in the 3D view (issue 35, as 3D Slicer's PR 8739
// does): up and down move what shows along HU, left and right stretch it; with the opacity
// modifier up and down scale the opacity instead. In iso the drag moves the threshold, in mip
// the window (up/down its level, left/right its width).
#include <glm/glm.hpp>

#include "no_qt.h"
#include "voxray/engine/render_params.h"

namespace voxray {

// START: the parameters when the drag began. MOVED: the drag so far in fractions of the view
// (x right, y up; a drag across the whole view is 1). HU_SPAN: HU for a drag across the
// view's height (the volume's value range). Stretch doubles per half view; the opacity
// doubles per third of the view.
RenderParams dragTransferFunction(const RenderParams& start, glm::dvec2 moved, double huSpan,
                                  bool opacity);

}  // namespace voxray
