#pragma once
// Which kernel variant a frame compiles to, by name (kernels/switches.h): frames with the same
// name run the same program. Tests enumerate variants by it.
#include <string>

#include "voxray/engine/render_params.h"

namespace voxray {

// e.g. "iso_shaded_zh_nearest_refine_steps4": the labels of the frame's switches.
std::string kernelVariantName(const RenderParams& p);

}  // namespace voxray
