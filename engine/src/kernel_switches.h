#pragma once
// The kernel switches of kernels/switches.h on the host: their values for a frame, the -D
// options that compile them, their slots in the frame parameters and the variant's name.
#include <string>

#include "voxray/engine/render_params.h"

namespace voxray {

struct RaycastParams;

struct KernelSwitches {
#define VOXRAY_SWITCH(NAME, DEFAULT, KIND, LABELS) int NAME = DEFAULT;
#include "switches.h"
#undef VOXRAY_SWITCH
};

// The switches a frame's parameters decide (the rest keep their defaults; the raycaster sets
// the storage, packet and output ones). A switch that cannot matter to the frame keeps its
// default (no gradient without shading, no refinement outside iso), so frames that differ
// only there share one program. The reference renderer follows the same rules.
KernelSwitches kernelSwitches(const RenderParams& p);

// " -D NAME=value" for every switch; with `uber`, FRAME switches read their slot at run time.
std::string switchOptions(const KernelSwitches& s, bool uber);
// Every switch's value into its slot of k.switches.
void packSwitches(const KernelSwitches& s, RaycastParams& k);
// The labels of switches.h joined by '_', e.g. "dvr_shaded_zh_oc" (test names, logs).
std::string variantName(const KernelSwitches& s);

}  // namespace voxray
