#pragma once
// The 3D view of a volume larger than the device (issue 38 part 2 in the workstation): whether
// the render worker draws it out of core (voxray/engine/out_of_core.h), what the out-of-core
// renderer cannot draw of a frame's parameters (turned off, and said), and what the view says
// while a drag's preview is not at full resolution. Qt-free: the worker and its tests use it.
#include <cstddef>
#include <string>
#include <vector>

#include "no_qt.h"
#include "voxray/engine/out_of_core.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/volume.h"

namespace voxray {

// Device bytes an in-core volume leaves for everything else on the device: the frame's image
// buffers (a 4K frame's float colour and hit buffers are about 300 MB), the empty-space cells,
// the light grid and other programs: an eighth of the device's memory plus 256 MiB.
size_t deviceHeadroomBytes(size_t globalMemBytes);

struct OutOfCoreChoice {
  bool outOfCore = false;
  size_t budgetBytes = 0;  // for OutOfCoreOptions::budgetBytes when outOfCore
};

// VOLUMEBYTES on a device of GLOBALMEMBYTES. USERBUDGETBYTES (the preference; 0: automatic):
// out of core when the volume is larger than it, in core otherwise (whatever the device). 0:
// out of core when the volume and the headroom do not fit the device's memory, within what the
// headroom leaves. (The in-core Raycaster splits a volume over its largest allocation into
// slabs, so that is no limit here; the out-of-core parts are each far below it.)
OutOfCoreChoice chooseOutOfCore(size_t volumeBytes, size_t globalMemBytes, size_t userBudgetBytes);

// What an out-of-core frame of P leaves out, as short phrases for the view ("labels",
// "fusion", "shadows (lit by phong)", ...), and P with them off. HASLABELS, HASOVERLAY: the worker
// holds a segmentation on the volume's grid, a fused overlay (the renderer draws neither);
// SPACINGZ: the volume's slice spacing (a step over 2 slices reads beyond a part's apron, so
// a longer step is shortened to 2 slices).
struct OutOfCoreParams {
  RenderParams params;
  std::vector<std::string> off;
};
OutOfCoreParams outOfCoreParams(const RenderParams& p, bool hasLabels, bool hasOverlay,
                                double spacingZMm);

// "Not at full resolution (3 of 8 parts)" while parts were drawn from the coarse level, plus
// "; quick preview, the coarse level on its way" while the source's quick level (slab_source.h)
// is shown, and "; device out of memory" when an upload failed; "" at full resolution.
std::string resolutionNote(const OutOfCoreStats& s);
// "Out of core, off: labels, fusion" for OFF; "" when nothing is off.
std::string limitsNote(const std::vector<std::string>& off);

}  // namespace voxray
