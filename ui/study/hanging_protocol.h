#pragma once
// Hanging protocols: rules that pick the layout, the slice window (a W/L preset) and the 3D
// transfer-function preset when a study opens, by its modality, body part and series
// description. The rules are a versioned JSON file in the user's config folder
// (hanging-protocols.json); without one the embedded default set applies. The first rule
// whose every given field matches wins. A field's pattern is a case-insensitive substring,
// or, written as /…/, a case-insensitive ECMAScript regex. A rule may also say which series
// of the study goes in which view ("series": {"axial": "T2", "3d": 2}): by a pattern on the
// series description, or by the series' place in the study (1-based, by series number).
#include <map>
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

// Which series a view shows: the first whose description matches DESCRIPTION (a pattern as
// the match fields'), or, with INDEX from 1, the study's INDEX-th series by series number.
struct SeriesChoice {
  std::string description;
  int index = 0;
  bool operator==(const SeriesChoice&) const = default;
};

struct HangingRule {
  std::string name;
  // Patterns; empty: any value.
  std::string modality, bodyPart, seriesDescription;
  std::optional<ViewLayout> layout;
  std::string window;  // a windowLevelPresets() name; empty: the study's own window
  std::string preset;  // a builtinPresets() name; empty: the 3D view keeps its preset
  std::map<GridView, SeriesChoice> series;  // none: every view shows the opened series
};

// The views RULE names, each with the series of STUDY it chooses, or empty with a note when
// no series fits (a missing series leaves the view empty; the rest still hang).
std::vector<PlacedView> placeSeries(const HangingRule& rule, const std::vector<StudySeries>& study);
// The series the grid shows (its views show one series at a time): that of the first cell of
// LAYOUT whose view PLACED fills; none when no placed view has a series.
std::optional<std::string> shownSeries(ViewLayout layout, const std::vector<PlacedView>& placed);
// The series shown beside it (compare's right column, linked in patient coordinates): that of
// the first cell of LAYOUT holding another series than SHOWN; none when every placed view
// holds SHOWN.
std::optional<PlacedView> besideSeries(ViewLayout layout, const std::vector<PlacedView>& placed,
                                       const std::string& shown);
// PLACED with the views that hold another series than SHOWN emptied, each with a note (the
// views show one series at a time).
std::vector<PlacedView> keepShown(std::vector<PlacedView> placed, const std::string& shown);
// As keepShown, keeping SHOWN and BESIDE (two series side by side); a third series' view is
// emptied with a note.
std::vector<PlacedView> keepShown(std::vector<PlacedView> placed, const std::string& shown,
                                  const std::string& beside);

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
