#include "render_state_model.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "voxray/engine/transfer_function.h"
#include "voxray/io/error.h"

namespace voxray::ui {

void RenderStateModel::update(unsigned what, const std::function<void(RenderParams&)>& edit) {
  edit(params_);
  changed.notify(what);
}

void RenderStateModel::setQuality(const Quality& q) {
  quality_ = q;
  quality_.stepScale = std::clamp(q.stepScale, 0.1, 8.0);
  quality_.interactiveDivisor = std::clamp(q.interactiveDivisor, 1, 8);
  changed.notify(kQuality);
}

void RenderStateModel::applyPreset(const std::string& name) {
  const Preset& preset = findPreset(name);
  update(kAppearance, [&](RenderParams& p) {
    voxray::applyPreset(p, preset);
    p.presetShiftHu = 0.0;
  });
}

void RenderStateModel::setPresetShift(double hu) {
  double clamped = std::clamp(hu, -kPresetShiftLimitHu, kPresetShiftLimitHu);
  update(kAppearance, [clamped](RenderParams& p) { p.presetShiftHu = clamped; });
}

std::string RenderStateModel::toText() const {
  std::ostringstream out;
  out << voxray::toText(params_);
  out << "ui-resolution=" << quality_.resolution.x << "," << quality_.resolution.y << "\n";
  out << "ui-step-scale=" << quality_.stepScale << "\n";
  return out.str();
}

void RenderStateModel::fromText(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  RenderParams p = params_;
  Quality q = quality_;
  while (std::getline(in, line)) {
    auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    try {
      if (key == "ui-resolution") {
        std::sscanf(value.c_str(), "%d,%d", &q.resolution.x, &q.resolution.y);
      } else if (key == "ui-step-scale") {
        q.stepScale = std::stod(value);
      } else if (key != "size") {  // the view decides the size
        voxray::fromText(p, line);
      }
    } catch (const std::exception&) {
      // Saved state from another version: keep the current value for this key.
    }
  }
  p.presetShiftHu = std::clamp(p.presetShiftHu, -kPresetShiftLimitHu, kPresetShiftLimitHu);
  params_ = p;
  setQuality(q);
  changed.notify(kAll);
}

RenderParams planFrame(const RenderParams& base, const Quality& q, const glm::ivec2& viewSize,
                       bool interactive, double minSpacingMm) {
  RenderParams p = base;
  glm::ivec2 size = q.resolution.x > 0 ? q.resolution : viewSize;
  double step = effectiveStepMm(base, minSpacingMm) * q.stepScale;
  if (interactive) {
    size /= q.interactiveDivisor;
    step *= q.interactiveStepScale;
  }
  size = glm::max(size, glm::ivec2(16));
  p.width = size.x;
  p.height = size.y;
  p.stepMm = step;
  return p;
}

}  // namespace voxray::ui
