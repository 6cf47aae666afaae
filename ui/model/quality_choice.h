#pragma once
// The quality control's choices, as text: the quality presets (resources/quality) with the
// error and speed measured for each, a "custom" choice (the render parameters' own step),
// and the resolution choice. Qt-free so the strings are tested without a display.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "no_qt.h"

namespace voxray::ui {

// The quality preset every frame rendered while the user drags uses, whatever the choice.
inline constexpr const char* kDragQualityPreset = "interactive";

struct QualityChoice {
  std::string preset;    // resources/quality name; empty = custom
  std::string label;     // "Balanced", "Custom"
  std::string measured;  // one line: "41.8 dB PSNR · 6.3× the reference's speed"
  std::string tooltip;   // the description, the measurement and what it was measured on
};

// The presets fastest first, then custom.
std::vector<QualityChoice> qualityChoices();
// "Window size" for {0, 0}, else "W × H".
std::string resolutionLabel(const glm::ivec2& size);

}  // namespace voxray::ui
