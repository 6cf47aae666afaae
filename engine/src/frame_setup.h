#pragma once
// What both renderers derive from (volume, parameters) before marching rays: the view,
// the lookup table, thresholds in stored units, the step. One place, so the kernel and
// the reference renderer cannot disagree about it.
#include "voxray/engine/camera.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/step.h"
#include "voxray/engine/transfer_function.h"

namespace voxray {

struct Volume;

struct FrameSetup {
  ViewGeometry view;
  Lut lut;
  double stepMm = 1.0;
  double referenceStepMm = 1.0;  // the step the preset's opacities are defined for
  double isoLoStored = 0.0, isoHiStored = 0.0;
  // iso: whether a stored value lies in the surface's range (the kernels' in_iso, lut.cl).
  bool inIso(double stored) const { return stored >= isoLoStored && stored <= isoHiStored; }
  double windowLoStored = 0.0, windowInvWidth = 1.0;  // mip grey mapping
};

// The transfer function a frame uses: the named preset's, or the mode's default.
TransferFunction frameTransferFunction(const RenderParams& p);
FrameSetup makeFrameSetup(const Volume& v, const RenderParams& p);

}  // namespace voxray
