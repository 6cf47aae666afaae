#pragma once
// The Pareto plot of `voxray-cli accuracy --plot`: error against milliseconds per frame,
// log-log, drawn on the lab's one plot canvas (plot_canvas.h).
#include <vector>

#include "voxray/io/image.h"
#include "voxray/lab/accuracy_sweep.h"

namespace voxray {

// Left panel: iso surface position error (voxels; the hit-point error where there is no
// analytic surface). Right panel: image RMSE against the reference. One colour per scene;
// the fastest-for-its-error frontier of each panel is joined by a line.
Image accuracyPlot(const std::vector<SweepRow>& rows);

}  // namespace voxray
