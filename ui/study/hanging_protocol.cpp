#include "hanging_protocol.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "voxray/engine/transfer_function.h"
#include "voxray/io/error.h"
#include "window_level.h"

namespace voxray {

namespace {

using nlohmann::json;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

bool isRegex(const std::string& p) { return p.size() >= 2 && p.front() == '/' && p.back() == '/'; }

std::regex compile(const std::string& pattern) {
  return std::regex(pattern.substr(1, pattern.size() - 2),
                    std::regex::ECMAScript | std::regex::icase);
}

std::string layoutList() {
  std::string out;
  for (ViewLayout l : viewLayouts()) out += (out.empty() ? "" : ", ") + layoutName(l);
  return out;
}

// The text at KEY of OBJ (absent: ""), FIELD naming it in errors.
std::string text(const json& obj, const char* key, const std::string& field) {
  if (!obj.contains(key)) return "";
  if (!obj[key].is_string()) throw inputError(field + ": give text");
  return obj[key].get<std::string>();
}

void refuseUnknownKeys(const json& obj, const std::vector<std::string>& known,
                       const std::string& where) {
  for (const auto& [key, value] : obj.items())
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw inputError(where + key + ": not a field of a hanging protocol; give " + list);
    }
}

void checkPattern(const std::string& pattern, const std::string& field) {
  if (!isRegex(pattern)) return;
  try {
    compile(pattern);
  } catch (const std::regex_error& e) {
    throw inputError(field + ": '" + pattern + "' is not a regular expression (" + e.what() + ")");
  }
}

}  // namespace

bool patternMatches(const std::string& pattern, const std::string& value) {
  if (pattern.empty()) return true;
  if (isRegex(pattern)) {
    try {
      return std::regex_search(value, compile(pattern));
    } catch (const std::regex_error&) {
      return false;  // parse refused it already; a hand-made rule simply does not match
    }
  }
  return lower(value).find(lower(pattern)) != std::string::npos;
}

const HangingRule* matchRule(const HangingProtocols& p, const StudyAttributes& s) {
  for (const HangingRule& r : p.rules)
    if (patternMatches(r.modality, s.modality) && patternMatches(r.bodyPart, s.bodyPart) &&
        patternMatches(r.seriesDescription, s.seriesDescription))
      return &r;
  return nullptr;
}

HangingProtocols parseHangingProtocols(const std::string& text_) {
  json doc;
  try {
    doc = json::parse(text_);
  } catch (const json::parse_error& e) {
    throw inputError(std::string("not JSON: ") + e.what());
  }
  if (!doc.is_object()) throw inputError("give a JSON object with \"voxray-hanging-protocols\"");
  refuseUnknownKeys(doc, {"voxray-hanging-protocols", "rules"}, "");
  if (!doc.contains("voxray-hanging-protocols") ||
      !doc["voxray-hanging-protocols"].is_number_integer())
    throw inputError("voxray-hanging-protocols: give the schema version (" +
                     std::to_string(kHangingProtocolVersion) + ")");
  const int version = doc["voxray-hanging-protocols"].get<int>();
  if (version > kHangingProtocolVersion || version < 1)
    throw inputError("voxray-hanging-protocols: version " + std::to_string(version) +
                     " is not one this build reads (" + std::to_string(kHangingProtocolVersion) +
                     "); update Voxray or write version " +
                     std::to_string(kHangingProtocolVersion));
  if (!doc.contains("rules") || !doc["rules"].is_array())
    throw inputError("rules: give a list of rules");
  HangingProtocols out;
  int i = 0;
  for (const json& r : doc["rules"]) {
    const std::string at = "rules[" + std::to_string(i++) + "].";
    if (!r.is_object()) throw inputError(at.substr(0, at.size() - 1) + ": give an object");
    refuseUnknownKeys(r, {"name", "match", "layout", "window", "preset", "series"}, at);
    HangingRule rule;
    rule.name = text(r, "name", at + "name");
    if (rule.name.empty()) throw inputError(at + "name: give each rule a name");
    if (r.contains("match")) {
      const json& m = r["match"];
      if (!m.is_object()) throw inputError(at + "match: give an object");
      refuseUnknownKeys(m, {"modality", "body-part", "series-description"}, at + "match.");
      rule.modality = text(m, "modality", at + "match.modality");
      rule.bodyPart = text(m, "body-part", at + "match.body-part");
      rule.seriesDescription = text(m, "series-description", at + "match.series-description");
      checkPattern(rule.modality, at + "match.modality");
      checkPattern(rule.bodyPart, at + "match.body-part");
      checkPattern(rule.seriesDescription, at + "match.series-description");
    }
    const std::string layout = text(r, "layout", at + "layout");
    if (!layout.empty()) {
      rule.layout = parseLayout(layout);
      if (!rule.layout)
        throw inputError(at + "layout: '" + layout + "' is not a layout; give one of " +
                         layoutList());
    }
    rule.window = text(r, "window", at + "window");
    if (!rule.window.empty()) {
      std::string names;
      bool known = false;
      for (const auto& p : windowLevelPresets()) {
        names += (names.empty() ? "" : ", ") + p.name;
        known = known || p.name == rule.window;
      }
      if (!known)
        throw inputError(at + "window: '" + rule.window + "' is not a window preset; give one of " +
                         names);
    }
    rule.preset = text(r, "preset", at + "preset");
    if (!rule.preset.empty()) {
      std::string names;
      bool known = false;
      for (const auto& p : builtinPresets()) {
        names += (names.empty() ? "" : ", ") + p.name;
        known = known || p.name == rule.preset;
      }
      if (!known)
        throw inputError(at + "preset: '" + rule.preset + "' is not a 3D preset; give one of " +
                         names);
    }
    if (r.contains("series")) {
      const json& views = r["series"];
      if (!views.is_object())
        throw inputError(at + "series: give an object of views, e.g. {\"axial\": \"T2\"}");
      for (const auto& [name, choice] : views.items()) {
        const std::string field = at + "series." + name;
        const auto view = parseGridView(name);
        if (!view) throw inputError(field + ": not a view; give 3d, axial, coronal or sagittal");
        SeriesChoice c;
        if (choice.is_number_integer() && choice.get<long long>() >= 1 &&
            choice.get<long long>() <= 10000) {
          c.index = choice.get<int>();
        } else if (choice.is_string() && !choice.get<std::string>().empty()) {
          c.description = choice.get<std::string>();
          checkPattern(c.description, field);
        } else {
          throw inputError(field +
                           ": give a series description pattern (text or /regex/) or the "
                           "series' place in the study (1, 2, ...)");
        }
        rule.series[*view] = c;
      }
    }
    out.rules.push_back(rule);
  }
  return out;
}

std::vector<PlacedView> placeSeries(const HangingRule& rule,
                                    const std::vector<StudySeries>& study) {
  std::vector<PlacedView> out;
  for (const auto& [view, choice] : rule.series) {
    PlacedView p;
    p.view = view;
    const StudySeries* found = nullptr;
    if (choice.index > 0) {
      if (size_t(choice.index) <= study.size())
        found = &study[size_t(choice.index - 1)];
      else
        p.note = "series " + std::to_string(choice.index) + " of the rule '" + rule.name +
                 "' is not in this study (it has " + std::to_string(study.size()) +
                 " volume series); the view is left empty";
    } else {
      for (const StudySeries& s : study)
        if (patternMatches(choice.description, s.description)) {
          found = &s;
          break;
        }
      if (!found)
        p.note = "no series of this study matches '" + choice.description + "' (rule '" +
                 rule.name + "'); the view is left empty";
    }
    if (found) {
      p.series = found->selector;
      p.uid = found->uid;
      p.description = found->description;
    }
    out.push_back(p);
  }
  return out;
}

std::optional<std::string> shownSeries(ViewLayout layout, const std::vector<PlacedView>& placed) {
  for (const LayoutCell& c : layoutCells(layout))
    for (const PlacedView& p : placed)
      if (p.view == c.view && !p.series.empty()) return p.series;
  return std::nullopt;
}

std::optional<PlacedView> besideSeries(ViewLayout layout, const std::vector<PlacedView>& placed,
                                       const std::string& shown) {
  for (const LayoutCell& c : layoutCells(layout))
    for (const PlacedView& p : placed)
      if (p.view == c.view && !p.series.empty() && p.series != shown) return p;
  return std::nullopt;
}

std::vector<PlacedView> keepShown(std::vector<PlacedView> placed, const std::string& shown,
                                  const std::string& beside) {
  for (PlacedView& p : placed)
    if (!p.series.empty() && p.series != shown && p.series != beside) {
      p.note = "its series '" + p.description +
               "' is a third one (two series show at once, side by side); the view is left "
               "empty";
      p.series.clear();
    }
  return placed;
}

std::vector<PlacedView> keepShown(std::vector<PlacedView> placed, const std::string& shown) {
  for (PlacedView& p : placed)
    if (!p.series.empty() && p.series != shown) {
      p.note = "its series '" + p.description +
               "' is not the one shown (the views show one series at a time); the view is "
               "left empty";
      p.series.clear();
    }
  return placed;
}

std::string hangingProtocolsJson(const HangingProtocols& p) {
  json rules = json::array();
  for (const HangingRule& r : p.rules) {
    json j{{"name", r.name}};
    json m = json::object();
    if (!r.modality.empty()) m["modality"] = r.modality;
    if (!r.bodyPart.empty()) m["body-part"] = r.bodyPart;
    if (!r.seriesDescription.empty()) m["series-description"] = r.seriesDescription;
    if (!m.empty()) j["match"] = m;
    if (r.layout) j["layout"] = layoutName(*r.layout);
    if (!r.window.empty()) j["window"] = r.window;
    if (!r.preset.empty()) j["preset"] = r.preset;
    for (const auto& [view, choice] : r.series)
      j["series"][gridViewName(view)] =
          choice.index > 0 ? json(choice.index) : json(choice.description);
    rules.push_back(j);
  }
  return json{{"voxray-hanging-protocols", kHangingProtocolVersion}, {"rules", rules}}.dump(2) +
         "\n";
}

const std::string& defaultHangingProtocolsJson() {
  // Reading habits: a head CT in brain window beside its bone rendering, a chest in lung
  // window with the slices first, MR on its own default look; any other CT in the classic grid.
  static const std::string text = R"({
  "voxray-hanging-protocols": 1,
  "rules": [
    {"name": "CT head", "match": {"modality": "CT", "series-description": "/head|brain|skull|cranium/"},
     "layout": "mpr+3d", "window": "Brain", "preset": "CT-Bone"},
    {"name": "CT chest", "match": {"modality": "CT", "series-description": "/chest|thorax|lung/"},
     "layout": "2x2", "window": "Lung", "preset": "CT-Skin"},
    {"name": "CT abdomen", "match": {"modality": "CT", "series-description": "/abdo|pelvis|liver/"},
     "layout": "2x2", "window": "Abdomen", "preset": "CT-Muscle"},
    {"name": "MR", "match": {"modality": "MR"}, "layout": "2x2", "preset": "MR-Default"}
  ]
}
)";
  return text;
}

HangingProtocols defaultHangingProtocols() {
  return parseHangingProtocols(defaultHangingProtocolsJson());
}

HangingProtocols loadHangingProtocols(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return defaultHangingProtocols();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw inputError(path + ": cannot be read; check its permissions");
  std::stringstream s;
  s << in.rdbuf();
  try {
    return parseHangingProtocols(s.str());
  } catch (const Error& e) {
    throw inputError(path + ": " + e.what());
  }
}

void saveHangingProtocols(const std::string& path, const HangingProtocols& p) {
  std::error_code ec;
  const auto folder = std::filesystem::path(path).parent_path();
  if (!folder.empty()) std::filesystem::create_directories(folder, ec);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << hangingProtocolsJson(p);
  if (!out) throw outputError(path + ": cannot be written; check the folder's permissions");
}

}  // namespace voxray
