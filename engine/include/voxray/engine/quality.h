#pragma once
// Quality presets (resources/quality/*.json): named speed/accuracy trades chosen from the
// accuracy sweep's measurements, each carrying the error and speed measured for it. The
// UI's quality control and interactive-drag mode apply one to the user's parameters.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/render_params.h"
#include "voxray/engine/step.h"

namespace voxray {

struct Volume;

struct QualityPreset {
  std::string name;  // interactive, balanced, reference
  std::string description;
  double stepVoxels = kDefaultStepVoxels;  // ray step in units of the smallest voxel spacing
  double resolutionScale = 1.0;            // image size factor (the drag mode renders smaller)
  Interp interp = Interp::Linear;
  Gradient gradient = Gradient::ZuckerHummel;
  int refine = 4;
  bool jitter = false;
  // Image-space adaptive sampling (RenderParams::adaptiveImage): threshold in levels (below 0:
  // off) and lattice spacing; keys "adaptive_image" and "adaptive_image_spacing".
  double adaptiveImage = -1.0;
  int adaptiveImageSpacing = 4;
  // Measured on CThead dvr (CT-Bone) by `voxray-cli accuracy`: PSNR against the
  // reference renderer at 1/16-voxel steps, and the speed-up over the reference preset.
  double measuredPsnrDb = 0.0;
  double measuredSpeedup = 1.0;
  double measuredMsPerFrame = 0.0;
  std::string measuredOn;  // device and image size of the measurement
};

// Throws Error (Input) naming `origin` and what is wrong.
QualityPreset parseQualityPreset(const std::string& json, const std::string& origin);
// resources/quality/*.json, embedded at build time, fastest first (by measured speed-up:
// interactive, balanced, reference).
const std::vector<QualityPreset>& builtinQualityPresets();
// By name, case-insensitive; throws Error (Input) listing the known names.
const QualityPreset& findQualityPreset(const std::string& name);

// p with the preset's step, reconstruction, gradient, refinement, jitter and image size.
RenderParams applyQuality(RenderParams p, const QualityPreset& q, double minSpacingMm);
RenderParams applyQuality(RenderParams p, const QualityPreset& q, const Volume& v);

// P as picking quality preset Q leaves it (the workstation's quality box, voxray-cli render
// --quality): the reconstruction and gradient Q was measured with, which the user may change
// afterwards. Its step, refinement, jitter and image scale apply per frame (settledFrame).
RenderParams pickQualityPreset(RenderParams p, const QualityPreset& q);

// The frame a view shows at rest, as the workstation plans it: BASE at the resolution
// choice (else VIEWSIZE), then QUALITYPRESET's step, refinement, jitter and image scale with
// BASE's reconstruction and gradient; custom (""): BASE's own effective step. At least
// 16x16. Throws Error (Input) for an unknown preset.
RenderParams settledFrame(const RenderParams& base, const std::string& qualityPreset,
                          const glm::ivec2& resolution, const glm::ivec2& viewSize,
                          double minSpacingMm);

}  // namespace voxray
