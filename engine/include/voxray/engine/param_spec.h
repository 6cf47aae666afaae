#pragma once
// A declared parameter with its domain (as F3D's options.json and ITK-SNAP's PropertyModel):
// its key, how to read and write it as text, and the values it may take, so that the command
// line, saved state and the workstation's controls take value and range from one place.
// Render parameters (render_params.h) and input flags (input_flags.h) are lists of these.
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace voxray {

// One value of an enumeration: the text that parses and formats it, the title a control
// shows, and other spellings that parse too.
struct EnumLabel {
  std::string name;
  std::string title;
  std::vector<std::string> aliases;
};

struct ParamDomain {
  std::vector<EnumLabel> labels;  // an enumeration's values in the enum's order; else empty
  // Numbers (each number of a list such as X,Y,Z): the accepted range, open where unset.
  std::optional<double> min, max;
  bool minExclusive = false;  // e.g. shininess > 0
  bool maxExclusive = false;
  double step = 1.0;  // a control's increment
  int decimals = 2;   // digits after the point a control shows
  std::string unit;   // a control's suffix ("HU"); empty: none
  // The ends a control offers where the range is open (a spin box needs ends): inside it.
  std::optional<double> uiMin, uiMax;

  // Chained settings for declarations, e.g. ParamDomain().above(0).offer({}, 1024).
  ParamDomain& choices(std::vector<EnumLabel> l);
  ParamDomain& atLeast(double v);
  ParamDomain& above(double v);  // exclusive
  ParamDomain& atMost(double v);
  ParamDomain& below(double v);  // exclusive
  ParamDomain& steps(double by, int shownDecimals);
  ParamDomain& in(std::string u);
  ParamDomain& offer(std::optional<double> lo, std::optional<double> hi);  // uiMin, uiMax

  bool contains(double v) const;
  // The range in words, e.g. "lie in 0 ... 1" or "be greater than 0" (after "must").
  std::string rangeText() const;
};

template <class Target>
struct Spec {
  std::string key;        // the flag without "--", and the key in saved state
  std::string valueHint;  // e.g. "iso|dvr|mip" or "X,Y,Z"
  std::string help;
  ParamDomain domain;
  std::function<void(Target&, const std::string&)> parse;  // throws Error (Input)
  std::function<std::string(const Target&)> format;
};

// The index of TEXT among LABELS (a name or an alias); throws Error (Input)
// "--KEY: 'TEXT' is not one of a, b, c".
size_t labelIndex(const std::string& key, const std::vector<EnumLabel>& labels,
                  const std::string& text);
// The labels' names joined by SEPARATOR ("iso|dvr|mip").
std::string labelNames(const std::vector<EnumLabel>& labels, const std::string& separator);
// V when DOMAIN contains it; throws Error (Input) "--KEY: must lie in 0 ... 1, got 'TEXT'".
double checkInDomain(const std::string& key, const ParamDomain& domain, double v,
                     const std::string& text);

}  // namespace voxray
