#include "voxray/engine/quality.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

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
      q.refine < 0 || q.refine > 16)
    throw inputError(origin +
                     ": step_voxels must be > 0, resolution_scale in (0, 1], refine "
                     "0 ... 16");
  return q;
}

std::vector<QualityPreset> loadQualityPresets(const std::string& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec))
    if (e.path().extension() == ".json") files.push_back(e.path());
  if (files.empty()) throw inputError(folder + ": no quality presets (*.json) here");
  std::sort(files.begin(), files.end());
  std::vector<QualityPreset> out;
  for (const auto& f : files) {
    std::ifstream in(f);
    std::stringstream text;
    text << in.rdbuf();
    out.push_back(parseQualityPreset(text.str(), f.string()));
  }
  return out;
}

RenderParams applyQuality(RenderParams p, const QualityPreset& q, const Volume& v) {
  double h = std::min({v.spacingMm.x, v.spacingMm.y, v.spacingMm.z});
  p.stepMm = q.stepVoxels * h;
  p.interp = q.interp;
  p.gradient = q.gradient;
  p.refine = q.refine;
  p.jitter = q.jitter;
  p.width = std::max(1, int(p.width * q.resolutionScale + 0.5));
  p.height = std::max(1, int(p.height * q.resolutionScale + 0.5));
  return p;
}

}  // namespace voxray
