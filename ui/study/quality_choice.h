#pragma once
// The quality control's choices, as text: the quality presets (resources/quality) with the
// error and speed measured for each, a "custom" choice (the render parameters' own step),
// and the resolution choice. Qt-free so the strings are tested without a display.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "no_qt.h"
#include "voxray/engine/render_params.h"

namespace voxray {

// The quality preset every frame rendered while the user drags uses, whatever the choice.
inline constexpr const char* kDragQualityPreset = "interactive";

struct QualityChoice {
  std::string preset;  // resources/quality name; empty = custom
  std::string label;   // "Balanced", "Custom"
  // "41.8 dB PSNR · 6.3× Reference's speed, measured on <where>": the figures come from
  // the preset's file, measured once where it says, not on this machine.
  std::string measured;
  std::string tooltip;  // the description, the measurement and what it was measured on
};

// The presets fastest first, then custom.
std::vector<QualityChoice> qualityChoices();
// What the figures of PRESET do not describe in P: "" when P samples with the
// reconstruction and gradient PRESET was measured with (or PRESET is custom), else e.g.
// "Not as measured: Central difference gradient (measured with Zucker-Hummel)". The
// Rendering group may change both after a preset was picked, and the command line or saved
// state may set them: the same label must not name two different renderings.
std::string qualityMismatch(const std::string& preset, const RenderParams& p);
// "Window size" for {0, 0}, else "W × H".
std::string resolutionLabel(const glm::ivec2& size);

}  // namespace voxray
