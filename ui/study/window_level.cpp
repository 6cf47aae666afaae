#include "window_level.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace voxray {

namespace {
constexpr double kMinWidth = 1.0;
}

const std::vector<WindowLevelPreset>& windowLevelPresets() {
  static const std::vector<WindowLevelPreset> presets = {
      {"Brain", {80, 40}},    {"Subdural", {215, 75}},    {"Stroke", {40, 40}},
      {"Lung", {1500, -600}}, {"Mediastinum", {350, 50}}, {"Abdomen", {400, 50}},
      {"Liver", {150, 30}},   {"Bone", {1800, 400}},
  };
  return presets;
}

const WindowLevelDomain& windowLevelDomain() {
  // The ends a spin box offers: wider than any CT window, and the levels from air to metal.
  static const WindowLevelDomain domain{
      ParamDomain().atLeast(kMinWidth).offer({}, 10000.0).steps(10.0, 0),
      ParamDomain().offer(-3000.0, 10000.0).steps(10.0, 0)};
  return domain;
}

uint8_t mapToGrey(double value, const WindowLevel& wl) {
  const double width = std::max(wl.width, kMinWidth);
  return greyRamp(value, wl.level - 0.5 * width, width);
}

uint8_t greyRamp(double value, double lo, double width) {
  return uint8_t(std::lround(std::clamp((value - lo) / width, 0.0, 1.0) * 255.0));
}

WindowLevel dragWindowLevel(const WindowLevel& start, double dx, double dy) {
  // One pixel changes the window by ~0.5 % of itself, at least 1 unit.
  double perPixel = std::max(1.0, 0.005 * start.width);
  WindowLevel wl;
  wl.width = std::max(kMinWidth, start.width + dx * perPixel);
  wl.level = start.level + dy * perPixel;
  return wl;
}

void WindowLevelModel::set(const WindowLevel& wl) {
  WindowLevel clamped{std::max(wl.width, kMinWidth), wl.level};
  if (clamped.width == wl_.width && clamped.level == wl_.level) return;
  wl_ = clamped;
  source_.clear();
  changed.notify();
}

void WindowLevelModel::reset(const WindowLevel& wl, std::string source) {
  wl_ = {std::max(wl.width, kMinWidth), wl.level};
  source_ = std::move(source);
  changed.notify();
}

std::string formatWindowLevel(const WindowLevel& wl, const std::string& source) {
  char text[64];
  std::snprintf(text, sizeof text, "W %.0f  L %.0f", wl.width, wl.level);
  return source.empty() ? std::string(text) : std::string(text) + "\n" + source;
}

bool WindowLevelModel::applyPreset(const std::string& name) {
  for (const auto& p : windowLevelPresets()) {
    if (p.name == name) {
      set(p.wl);
      return true;
    }
  }
  return false;
}

}  // namespace voxray
