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

// What the raycaster knows beyond a frame's parameters: its options, the volume's storage on
// the device and whether it marches packets (CPUs).
struct KernelFacts {
  bool emptySpaceSkipping = false;
  bool storageImage = false;  // image3d_t, else a buffer
  int slabs = 1;              // the volume's z slabs on the device
  bool countSamples = false;
  bool hitOutput = false;  // renderWithHits
  int packetLanes = 0;     // packets of 8 or 16 lanes; 0: one ray per work-item
  // A dvr frame with a segmentation whose table changes something (Raycaster::setSegmentation).
  bool labels = false;
  // ... where also a segment has its own transfer function (segment_tf.h, segmentTfSlots).
  bool segmentTf = false;
  // A dvr frame of a raycaster that holds an overlay (Raycaster::setOverlay).
  bool overlay = false;
  // A dvr frame with a segment shown as a surface (Raycaster's surface pass).
  bool surfaces = false;
  // The raycaster makes the pre-integrated table (RenderParams::preintegrate; PREINT).
  bool preintegrate = false;
};

// The switches a frame's parameters decide (the rest keep their defaults). A switch that
// cannot matter to the frame keeps its default (no gradient without shading, no refinement
// outside iso), so frames that differ only there share one program. The reference renderer
// follows the same rules.
KernelSwitches kernelSwitches(const RenderParams& p);
// The raycaster's switches: the frame's, then the storage, output and packet ones from `f`.
KernelSwitches kernelSwitches(const RenderParams& p, const KernelFacts& f);

// " -D NAME=value" for every switch; with `uber`, FRAME switches read their slot at run time.
// A PACKET variant also gets the tuning of switches.h (VOXRAY_TUNING) for its LANES.
std::string switchOptions(const KernelSwitches& s, bool uber);
// Every switch's value into its slot of k.switches.
void packSwitches(const KernelSwitches& s, RaycastParams& k);
// The labels of switches.h joined by '_', e.g. "dvr_shaded_zh_oc" (test names, logs, accuracy
// rows); a shaded frame names its gradient also when it is the default ("iso_shaded_central").
std::string variantName(const KernelSwitches& s);

}  // namespace voxray
