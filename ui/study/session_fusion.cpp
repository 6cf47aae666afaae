// The session's "fusion": the overlay volume, its colour map, window and opacity, and a 4D
// overlay's own time point (issue 36).
#include "session_sections.h"

#include <cmath>

#include "fusion.h"

namespace voxray {

namespace session_detail {

Json fusionJson(const Session::Fusion& f, const std::string& sessionPath) {
  return {{"input", inputJson(f.input, sessionPath)},
          {"on", f.on},
          {"colormap", f.colormap},
          {"window", {{"lo", f.lo}, {"hi", f.hi}, {"unit", f.unit}}},
          {"opacity", f.opacity},
          {"time-point", f.timePoint}};
}

// An optional time point (a 4D overlay's or prior's own) at KEY of J, FIELD naming it.
int readTimePoint(Reader& r, const Json& j, const char* key, const std::string& field) {
  if (!j.contains(key)) return 0;
  const Json& t = j.at(key);
  if (!t.is_number_integer() || t.get<long long>() < 0 || t.get<long long>() > 100000)
    r.fail(field, "must be a time point, 0 or more");
  return int(t.get<long long>());
}

void readFusion(Reader& r, const Json& root, const std::string& sessionPath, SessionRead& out) {
  if (!root.contains("fusion")) return;
  const Json& j = r.object(root, "fusion", "fusion");
  r.warnUnknown(j, "fusion.", {"input", "on", "colormap", "window", "opacity", "time-point"});
  Session::Fusion f;
  readInputObject(r, r.object(j, "fusion.input", "input"), "fusion.input", sessionPath, f.input,
                  out.missingFusion);
  if (f.input.path.empty()) r.fail("fusion.input.path", "must name the overlay's file or folder");
  if (j.contains("on")) {
    if (!j.at("on").is_boolean()) r.fail("fusion.on", "must be true or false");
    f.on = j.at("on").get<bool>();
  }
  f.colormap = r.text(r.require(j, "fusion.colormap", "colormap"), "fusion.colormap");
  const auto& maps = fusionColormaps();
  if (std::find(maps.begin(), maps.end(), f.colormap) == maps.end()) {
    std::string names;
    for (const auto& m : maps) names += (names.empty() ? "" : ", ") + m;
    r.fail("fusion.colormap", "must be one of " + names);
  }
  const Json& window = r.object(j, "fusion.window", "window");
  r.warnUnknown(window, "fusion.window.", {"lo", "hi", "unit"});
  f.lo = r.number(r.require(window, "fusion.window.lo", "lo"), "fusion.window.lo");
  f.hi = r.number(r.require(window, "fusion.window.hi", "hi"), "fusion.window.hi");
  if (!std::isfinite(f.lo) || !std::isfinite(f.hi) || !(f.lo < f.hi))
    r.fail("fusion.window", "must have lo below hi (finite numbers in the overlay's unit)");
  if (window.contains("unit")) f.unit = r.text(window.at("unit"), "fusion.window.unit");
  f.opacity = r.number(r.require(j, "fusion.opacity", "opacity"), "fusion.opacity");
  if (!(f.opacity >= 0.0 && f.opacity <= 1.0)) r.fail("fusion.opacity", "must be 0 ... 1");
  f.timePoint = readTimePoint(r, j, "time-point", "fusion.time-point");
  out.session.fusion = f;
}

}  // namespace session_detail

}  // namespace voxray
