#pragma once
// What both renderers derive from (volume, parameters) before marching rays: the view,
// the lookup table, thresholds in stored units, the step. One place, so the kernel and
// the reference renderer cannot disagree about it.
#include <string>
#include <vector>

#include "voxray/engine/camera.h"
#include "voxray/engine/preint_table.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/tf2d.h"
#include "voxray/engine/transfer_function.h"

namespace voxray {

struct Volume;

// Exactly the parameters the costly part of a setup reads (its table and thresholds; the
// window costs two passes over the volume for its value range). That part is made from
// this key alone (makeValueSetup), so it cannot read a field the raycaster's cache does not
// compare: a field it needs must be added here first.
struct SetupKey {
  Mode mode = Mode::Iso;
  std::string preset;
  double presetShiftHu = 0.0;
  std::vector<ControlPoint> transferFunction;
  double opacityUnitMm = 0.0;
  std::vector<glm::dvec2> gradientOpacity;  // dvr only: other modes leave it empty
  Tf2d tf2d;                                // likewise
  glm::dvec3 surfaceColor{0.0};
  double isoLo = 0.0, isoHi = 0.0;
  double windowWidth = 0.0, windowLevel = 0.0;
  bool operator==(const SetupKey&) const = default;
};
SetupKey setupKeyOf(const RenderParams& p);

struct FrameSetup {
  ViewGeometry view;
  Lut lut;
  GradientTable gradient;  // dvr's gradient opacity; empty: off
  // dvr's 2D transfer function; empty: off. With it, lut holds the table's largest opacity over
  // gradient (reduceTf2dToLut) for what reads the 1D table: empty-space skipping, the light grid.
  Tf2dTable tf2d;
  // dvr's pre-integrated table (PREINT) for this step; empty: off. Made by
  // DeviceFrame::updateSetup where the raycaster asks for it, again when the table or the step
  // changes (placeFrame and makeValueSetup leave it empty).
  PreintTable preint;
  double stepMm = 1.0;
  double referenceStepMm = 1.0;  // the step the preset's opacities are defined for
  double isoLoStored = 0.0, isoHiStored = 0.0;
  // iso: whether a stored value lies in the surface's range (the kernels' in_iso, lut.cl).
  bool inIso(double stored) const { return stored >= isoLoStored && stored <= isoHiStored; }
  double windowLoStored = 0.0, windowInvWidth = 1.0;  // mip grey mapping
};

// The transfer function a frame uses: the named preset's, or the mode's default.
TransferFunction frameTransferFunction(const SetupKey& k);
TransferFunction frameTransferFunction(const RenderParams& p);
// The setup's costly part: table, thresholds, window and reference step; no view or step.
// RANGE: V's storedRange, when the caller keeps it (a pass over the volume otherwise).
FrameSetup makeValueSetup(const Volume& v, const SetupKey& k, const ValueRange& range);
FrameSetup makeValueSetup(const Volume& v, const SetupKey& k);
// The per-frame part into S (made by makeValueSetup for P's key): P's view and step.
void placeFrame(FrameSetup& s, const Volume& v, const RenderParams& p);
FrameSetup makeFrameSetup(const Volume& v, const RenderParams& p);

}  // namespace voxray
