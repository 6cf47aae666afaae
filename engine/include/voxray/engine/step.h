#pragma once
// The ray step in one shape. RenderParams::stepMm is in mm, 0 meaning the default; the
// quality presets, the drag controller and the lighting figures count steps in units of the
// volume's smallest voxel spacing. These are the one conversion between the two and the one
// home of the default, so that a frame planned in voxels and read back in voxels (the drag
// controller's round trip) cannot disagree with the step the renderers march.
#include "voxray/engine/render_params.h"

namespace voxray {

// The step of stepMm 0: half the smallest voxel spacing.
inline constexpr double kDefaultStepVoxels = 0.5;

// STEPVOXELS (units of the smallest spacing MINSPACINGMM) in mm; 0 stays 0, the default.
inline double stepMmOf(double stepVoxels, double minSpacingMm) { return stepVoxels * minSpacingMm; }

// The step in mm actually marched: STEPMM when set (> 0), else the default.
inline double effectiveStepMm(double stepMm, double minSpacingMm) {
  return stepMm > 0.0 ? stepMm : stepMmOf(kDefaultStepVoxels, minSpacingMm);
}
inline double effectiveStepMm(const RenderParams& p, double minSpacingMm) {
  return effectiveStepMm(p.stepMm, minSpacingMm);
}

// The step actually marched for STEPMM (0: the default), in units of the smallest spacing.
inline double stepVoxelsOf(double stepMm, double minSpacingMm) {
  return effectiveStepMm(stepMm, minSpacingMm) / minSpacingMm;
}

}  // namespace voxray
