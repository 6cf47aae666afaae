#include "reading_keymap.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "voxray/io/error.h"

namespace voxray {

const std::vector<std::string>& numberKeyWindows() {
  // The windows a CT reading switches between most, in the order radiologists' keys have
  // them (RadiAnt and Horos put brain first and bone last).
  static const std::vector<std::string> names = {"Brain",       "Subdural", "Lung",
                                                 "Mediastinum", "Abdomen",  "Bone"};
  return names;
}

const std::vector<ReadingAction>& defaultReadingActions() {
  static const std::vector<ReadingAction> actions = [] {
    std::vector<ReadingAction> a = {
        {"layout-1x1", "Layout 1×1 (axial)", "Ctrl+1"},
        {"layout-1x2", "Layout 1×2 (axial and 3D)", "Ctrl+2"},
        {"layout-2x2", "Layout 2×2 (slices first)", "Ctrl+3"},
        {"layout-1+3", "Layout 1+3 (large axial)", "Ctrl+4"},
        {"layout-mpr+3d", "Layout MPR+3D", "Ctrl+5"},
        {"layout-3d", "Layout 3D only", "Ctrl+6"},
    };
    for (size_t i = 0; i < numberKeyWindows().size(); ++i)
      a.push_back({"window-" + std::to_string(i + 1), "Window " + numberKeyWindows()[i],
                   std::to_string(i + 1)});
    const std::vector<ReadingAction> rest = {
        {"next-series", "Next series of the study", "N"},
        {"previous-series", "Previous series of the study", "Shift+N"},
        {"next-study", "Next study in the browser's list", "]"},
        {"previous-study", "Previous study in the browser's list", "["},
        {"page-forward", "Page forward (a slab, or 10 slices)", "PgUp"},
        {"page-back", "Page back (a slab, or 10 slices)", "PgDown"},
        {"tool-probe", "Probe (pointer with the value readout)", "P"},
        {"tool-distance", "Distance tool", "D"},
        {"tool-angle", "Angle tool", "A"},
        {"tool-roi", "ROI tool (ellipse)", "E"},
        {"tool-text", "Text annotation tool", "T"},
        {"tool-arrow", "Arrow annotation tool", "W"},
        {"mark-key-image", "Mark key image", "K"},
    };
    a.insert(a.end(), rest.begin(), rest.end());
    return a;
  }();
  return actions;
}

std::string plainKeyNormaliser(const std::string& key) {
  std::string out;
  for (unsigned char c : key)
    if (!std::isspace(c)) out += char(std::toupper(c));
  return out;
}

void checkKeymap(const std::vector<ReadingAction>& actions, const KeyNormaliser& normalise) {
  std::map<std::string, const ReadingAction*> taken;
  for (const ReadingAction& a : actions) {
    if (a.key.empty()) continue;  // no key: only the menu
    const std::string k = normalise(a.key);
    if (k.empty())
      throw inputError("keys." + a.id + ": '" + a.key +
                       "' is not a key; write it as Qt does, e.g. \"N\", \"Shift+N\", \"Ctrl+1\", "
                       "\"PgUp\"");
    auto [it, fresh] = taken.emplace(k, &a);
    if (!fresh)
      throw inputError("keys." + a.id + ": '" + a.key + "' is given to both '" + it->second->title +
                       "' (" + it->second->id + ") and '" + a.title + "' (" + a.id +
                       "); give each action its own key");
  }
}

int pageSlices(double slabMm, double sliceSpacingMm) {
  if (slabMm <= 0.0 || sliceSpacingMm <= 0.0) return 10;
  return std::max(1, int(std::lround(slabMm / sliceSpacingMm)));
}

ReadingKeymap::ReadingKeymap() : actions_(defaultReadingActions()) {}

const std::string& ReadingKeymap::key(const std::string& id) const {
  static const std::string none;
  for (const auto& a : actions_)
    if (a.id == id) return a.key;
  return none;
}

void ReadingKeymap::setKey(const std::string& id, const std::string& key,
                           const KeyNormaliser& normalise) {
  auto next = actions_;
  auto it = std::find_if(next.begin(), next.end(), [&](const auto& a) { return a.id == id; });
  if (it == next.end()) throw inputError("keys." + id + ": not a reading action");
  it->key = key;
  checkKeymap(next, normalise);
  actions_ = std::move(next);
}

void ReadingKeymap::applyJson(const std::string& text, const KeyNormaliser& normalise) {
  using nlohmann::json;
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw inputError(std::string("not JSON: ") + e.what());
  }
  if (!doc.is_object() || !doc.contains("voxray-keymap") ||
      !doc["voxray-keymap"].is_number_integer())
    throw inputError("voxray-keymap: give the schema version (" + std::to_string(kKeymapVersion) +
                     ")");
  const int version = doc["voxray-keymap"].get<int>();
  if (version < 1 || version > kKeymapVersion)
    throw inputError("voxray-keymap: version " + std::to_string(version) +
                     " is not one this build reads (" + std::to_string(kKeymapVersion) + ")");
  for (const auto& [k, v] : doc.items())
    if (k != "voxray-keymap" && k != "keys")
      throw inputError(k + ": not a field of a keymap; give voxray-keymap and keys");
  if (!doc.contains("keys") || !doc["keys"].is_object())
    throw inputError("keys: give an object of action id to key");
  auto next = actions_;
  for (const auto& item : doc["keys"].items()) {
    const std::string& id = item.key();
    const auto& key = item.value();
    auto it = std::find_if(next.begin(), next.end(), [&](const auto& a) { return a.id == id; });
    if (it == next.end()) {
      std::string ids;
      for (const auto& a : next) ids += (ids.empty() ? "" : ", ") + a.id;
      throw inputError("keys." + id + ": not a reading action; give one of " + ids);
    }
    if (!key.is_string()) throw inputError("keys." + id + ": give the key as text");
    it->key = key.get<std::string>();
  }
  checkKeymap(next, normalise);
  actions_ = std::move(next);
}

std::string ReadingKeymap::toJson() const {
  nlohmann::ordered_json keys = nlohmann::ordered_json::object();
  for (const auto& a : actions_) keys[a.id] = a.key;
  return nlohmann::ordered_json{{"voxray-keymap", kKeymapVersion}, {"keys", keys}}.dump(2) + "\n";
}

void ReadingKeymap::load(const std::string& path, const KeyNormaliser& normalise) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw inputError(path + ": cannot be read; check its permissions");
  std::stringstream s;
  s << in.rdbuf();
  try {
    applyJson(s.str(), normalise);
  } catch (const Error& e) {
    throw inputError(path + ": " + e.what());
  }
}

}  // namespace voxray
