#include "voxray/engine/quality.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <string_view>

#include <nlohmann/json.hpp>

#include "voxray/engine/step.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

const std::map<std::string, std::string_view>& embeddedQualityPresets();  // generated at build

QualityPreset parseQualityPreset(const std::string& text, const std::string& origin) {
  QualityPreset q;
  try {
    auto j = nlohmann::json::parse(text);
    q.name = j.at("name").get<std::string>();
    q.description = j.value("description", "");
    q.stepVoxels = j.at("step_voxels").get<double>();
    q.resolutionScale = j.value("resolution_scale", 1.0);
    q.interp = parseInterp(j.value("interp", "linear"));
    q.gradient = parseGradient(j.value("gradient", "zucker-hummel"));
    q.refine = j.value("refine", 4);
    q.jitter = j.value("jitter", false);
    q.adaptiveImage = j.value("adaptive_image", -1.0);
    q.adaptiveImageSpacing = j.value("adaptive_image_spacing", 4);
    if (j.contains("measured")) {
      const auto& m = j["measured"];
      q.measuredPsnrDb = m.value("psnr_db", 0.0);
      q.measuredSpeedup = m.value("speedup_vs_reference", 1.0);
      q.measuredMsPerFrame = m.value("ms_per_frame", 0.0);
      q.measuredOn = m.value("on", "");
    }
  } catch (const nlohmann::json::exception& e) {
    throw inputError(origin + ": not a quality preset: " + e.what());
  }
  if (!(q.stepVoxels > 0.0) || !(q.resolutionScale > 0.0 && q.resolutionScale <= 1.0) ||
      q.refine < 0 || q.refine > 16 || q.adaptiveImage > 255.0 || q.adaptiveImageSpacing < 2 ||
      q.adaptiveImageSpacing > 8)
    throw inputError(origin +
                     ": step_voxels must be > 0, resolution_scale in (0, 1], refine "
                     "0 ... 16, adaptive_image at most 255 (below 0: off), "
                     "adaptive_image_spacing 2 ... 8");
  return q;
}

const std::vector<QualityPreset>& builtinQualityPresets() {
  static const std::vector<QualityPreset> presets = [] {
    std::vector<QualityPreset> out;
    for (const auto& [name, text] : embeddedQualityPresets())
      out.push_back(parseQualityPreset(std::string(text), "resources/quality/" + name));
    std::stable_sort(out.begin(), out.end(), [](const QualityPreset& a, const QualityPreset& b) {
      return a.measuredSpeedup > b.measuredSpeedup;
    });
    return out;
  }();
  return presets;
}

const QualityPreset& findQualityPreset(const std::string& name) {
  auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
  };
  std::string known;
  for (const auto& q : builtinQualityPresets()) {
    if (lower(q.name) == lower(name)) return q;
    known += (known.empty() ? "" : ", ") + q.name;
  }
  throw inputError("unknown quality preset '" + name + "'; known: " + known);
}

RenderParams pickQualityPreset(RenderParams p, const QualityPreset& q) {
  p.interp = q.interp;
  p.gradient = q.gradient;
  return p;
}

RenderParams applyQuality(RenderParams p, const QualityPreset& q, double minSpacingMm) {
  p = pickQualityPreset(std::move(p), q);
  p.stepMm = stepMmOf(q.stepVoxels, minSpacingMm);
  p.refine = q.refine;
  p.jitter = q.jitter;
  if (q.adaptiveImage >= 0.0) {  // a preset without the key keeps the frame's own choice
    p.adaptiveImage = q.adaptiveImage;
    p.adaptiveImageSpacing = q.adaptiveImageSpacing;
  }
  p.width = std::max(1, int(p.width * q.resolutionScale + 0.5));
  p.height = std::max(1, int(p.height * q.resolutionScale + 0.5));
  return p;
}

RenderParams applyQuality(RenderParams p, const QualityPreset& q, const Volume& v) {
  return applyQuality(std::move(p), q, v.minSpacingMm());
}

RenderParams settledFrame(const RenderParams& base, const std::string& qualityPreset,
                          const glm::ivec2& resolution, const glm::ivec2& viewSize,
                          double minSpacingMm) {
  RenderParams p = base;
  const glm::ivec2 size = resolution.x > 0 ? resolution : viewSize;
  p.width = size.x;
  p.height = size.y;
  if (!qualityPreset.empty()) {
    p = applyQuality(p, findQualityPreset(qualityPreset), minSpacingMm);
    p.interp = base.interp;      // the user's, set to the preset's when it was picked
    p.gradient = base.gradient;  // (pickQualityPreset)
  } else {
    p.stepMm = effectiveStepMm(base, minSpacingMm);
  }
  p.width = std::max(p.width, 16);
  p.height = std::max(p.height, 16);
  return p;
}

}  // namespace voxray
