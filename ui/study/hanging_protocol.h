#pragma once
// Hanging protocols: rules that pick the layout, the slice window (a W/L preset) and the 3D
// transfer-function preset when a study opens, by its modality, body part and series
// description. The rules are a versioned JSON file in the user's config folder
// (hanging-protocols.json); without one the embedded default set applies. The first rule
// whose every given field matches wins. A field's pattern is a case-insensitive substring,
// or, written as /…/, a case-insensitive ECMAScript regex.
#include <optional>
#include <string>
#include <vector>

#include "layout_model.h"
#include "no_qt.h"

namespace voxray {

constexpr int kHangingProtocolVersion = 1;

struct StudyAttributes {
  std::string modality, bodyPart, seriesDescription;
};

struct HangingRule {
  std::string name;
  // Patterns; empty: any value.
  std::string modality, bodyPart, seriesDescription;
  std::optional<ViewLayout> layout;
  std::string window;  // a windowLevelPresets() name; empty: the study's own window
  std::string preset;  // a builtinPresets() name; empty: the 3D view keeps its preset
};

struct HangingProtocols {
  std::vector<HangingRule> rules;
};

// Whether PATTERN (substring or /regex/, case-insensitive) matches VALUE; empty matches all.
bool patternMatches(const std::string& pattern, const std::string& value);
// The first rule matching S, or none.
const HangingRule* matchRule(const HangingProtocols& p, const StudyAttributes& s);

// Reads the rules' JSON. Throws Error (Input) naming the field ("rules[1].layout: 'x' is not
// a layout; give one of …"): not JSON, a newer version, an unknown key, an unknown layout,
// window or 3D preset, a regex that does not compile, a rule without a name.
HangingProtocols parseHangingProtocols(const std::string& json);
std::string hangingProtocolsJson(const HangingProtocols& p);  // what parse reads back
// The embedded default set (as JSON text, and parsed).
const std::string& defaultHangingProtocolsJson();
HangingProtocols defaultHangingProtocols();

// The rules of PATH: the defaults when the file does not exist; throws (as parse, the
// message starting with PATH) when it is unreadable or wrong.
HangingProtocols loadHangingProtocols(const std::string& path);
// Writes P to PATH (its folder made); throws Error (Output) when it cannot.
void saveHangingProtocols(const std::string& path, const HangingProtocols& p);

}  // namespace voxray
