#include <algorithm>
#include <cctype>
#include <map>
#include <string_view>

#include <nlohmann/json.hpp>

#include "voxray/engine/render_params.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/io/error.h"

namespace voxray {

const std::map<std::string, std::string_view>& embeddedPresets();  // generated at build time

Preset parsePreset(const std::string& text, const std::string& origin) {
  try {
    auto j = nlohmann::json::parse(text);
    Preset p;
    p.name = j.at("name").get<std::string>();
    p.description = j.value("description", "");
    p.mode = j.value("mode", "dvr");
    if (p.mode != "iso" && p.mode != "dvr" && p.mode != "mip")
      throw inputError(origin + ": mode '" + p.mode + "' is not iso, dvr or mip");
    for (const auto& pt : j.value("points", nlohmann::json::array())) {
      if (!pt.is_array() || pt.size() != 5)
        throw inputError(origin + ": each point must be [hu, r, g, b, opacity]");
      p.tf.points.push_back(
          {pt[0].get<double>(),
           {pt[1].get<double>(), pt[2].get<double>(), pt[3].get<double>(), pt[4].get<double>()}});
    }
    std::stable_sort(p.tf.points.begin(), p.tf.points.end(),
                     [](const ControlPoint& a, const ControlPoint& b) { return a.hu < b.hu; });
    if (j.contains("iso")) {
      p.isoLo = j["iso"].at(0).get<double>();
      p.isoHi = j["iso"].at(1).get<double>();
    }
    if (j.contains("window")) {
      p.windowWidth = j["window"].at(0).get<double>();
      p.windowLevel = j["window"].at(1).get<double>();
    }
    return p;
  } catch (const nlohmann::json::exception& e) {
    throw inputError(origin + ": not a valid preset (" + std::string(e.what()) + ")");
  }
}

const std::vector<Preset>& builtinPresets() {
  static const std::vector<Preset> presets = [] {
    std::vector<Preset> out;
    for (const auto& [name, text] : embeddedPresets())
      out.push_back(parsePreset(std::string(text), "resources/presets/" + name));
    return out;
  }();
  return presets;
}

void applyPreset(RenderParams& p, const Preset& preset) {
  p.preset = preset.name;
  p.transferFunction.clear();  // the preset's table, not an earlier custom one
  p.presetShiftHu = 0.0;       // a shift tuned for one preset means nothing for another
  p.opacityUnitMm = 0.0;       // preset opacities are per smallest voxel spacing
  p.mode = parseMode(preset.mode);
  if (preset.isoHi > preset.isoLo) {
    p.isoLo = preset.isoLo;
    p.isoHi = preset.isoHi;
  }
  if (preset.windowWidth > 0.0) {
    p.windowWidth = preset.windowWidth;
    p.windowLevel = preset.windowLevel;
  }
}

const Preset& findPreset(const std::string& name) {
  auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
  };
  std::string known;
  for (const auto& p : builtinPresets()) {
    if (lower(p.name) == lower(name)) return p;
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw inputError("unknown preset '" + name + "'; known presets: " + known);
}

}  // namespace voxray
