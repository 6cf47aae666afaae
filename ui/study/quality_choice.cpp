#include "quality_choice.h"

#include <cctype>
#include <cstdio>

#include "voxray/engine/quality.h"

namespace voxray {

namespace {

std::string measuredLine(const QualityPreset& q) {
  char b[160];
  std::snprintf(b, sizeof b, "%.1f dB PSNR \u00b7 %.1f\u00d7 Reference's speed", q.measuredPsnrDb,
                q.measuredSpeedup);
  return std::string(b) + ", measured on " + q.measuredOn;
}

std::string title(const std::string& key, int index) {
  return findRenderParamSpec(key).domain.labels[size_t(index)].title;
}

std::string tooltip(const QualityPreset& q) {
  char b[512];
  std::snprintf(b, sizeof b,
                "%s\nMeasured: %.2f dB PSNR against the reference renderer at 1/16-voxel steps, "
                "%.1f ms per frame, %.1f\u00d7 the reference preset's speed\n(%s)",
                q.description.c_str(), q.measuredPsnrDb, q.measuredMsPerFrame, q.measuredSpeedup,
                q.measuredOn.c_str());
  return b;
}

}  // namespace

std::vector<QualityChoice> qualityChoices() {
  std::vector<QualityChoice> out;
  for (const QualityPreset& q : builtinQualityPresets()) {
    std::string label = q.name;
    if (!label.empty()) label[0] = char(std::toupper(static_cast<unsigned char>(label[0])));
    out.push_back({q.name, label, measuredLine(q), tooltip(q)});
  }
  out.push_back({"", "Custom", "not measured",
                 "The render parameters' own step, refinement and jitter (voxray-cli flags); "
                 "frames while dragging still use the interactive preset"});
  return out;
}

std::string qualityMismatch(const std::string& preset, const RenderParams& p) {
  if (preset.empty()) return "";
  const QualityPreset& q = findQualityPreset(preset);
  std::string out;
  auto add = [&out](const std::string& part) { out += (out.empty() ? "" : "; ") + part; };
  if (p.gradient != q.gradient)
    add(title("gradient", int(p.gradient)) + " gradient (measured with " +
        title("gradient", int(q.gradient)) + ")");
  if (p.interp != q.interp)
    add(title("interp", int(p.interp)) + " sampling (measured with " +
        title("interp", int(q.interp)) + ")");
  return out.empty() ? out : "Not as measured: " + out;
}

std::string resolutionLabel(const glm::ivec2& size) {
  if (size.x <= 0 || size.y <= 0) return "Window size";
  return std::to_string(size.x) + " \u00d7 " + std::to_string(size.y);
}

}  // namespace voxray
