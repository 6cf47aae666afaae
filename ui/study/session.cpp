#include "session.h"

#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "segmentation_json.h"
#include "session_sections.h"
#include "voxray/engine/quality.h"
#include "voxray/io/error.h"

namespace voxray {

using namespace session_detail;

namespace {

constexpr const char* kVersionKey = "voxray-session";
constexpr int kMaxDepth = 256;
// A session object holds tens of fields; an object with more is not one, and reading it would
// not end soon (ordered_json compares each key with every earlier one of its object: 300,000
// keys took minutes, 2,000 objects of 1,000 keys 10 s).
constexpr size_t kMaxFields = 1000, kMaxFieldsInAll = 100000;

}  // namespace

const std::vector<std::string>& sessionLayouts() {
  static const std::vector<std::string> names = {"grid", "3d", "axial", "coronal", "sagittal"};
  return names;
}

std::string sessionToJson(const Session& s, const std::string& sessionPath) {
  Json j;
  j[kVersionKey] = kSessionVersion;
  j["input"] = inputJson(s.input, sessionPath);
  Json render = Json::object();
  for (const auto& spec : renderParamSpecs()) render[spec.key] = spec.format(s.render);
  j["render"] = render;
  j["quality"] = {{"preset", s.qualityPreset}, {"resolution", {s.resolution.x, s.resolution.y}}};
  j["slices"] = {{"window-width", s.window.width},
                 {"window-level", s.window.level},
                 {"crosshair", {s.crosshair.x, s.crosshair.y, s.crosshair.z}},
                 {"interp", toString(s.sliceInterp)}};
  if (s.centre) j["slices"]["centre"] = {s.centre->x, s.centre->y, s.centre->z};
  if (Json views = viewsJson(s.views); !views.empty()) j["slices"]["views"] = views;
  j["layout"] = s.layout;
  j["overlays"] = {{"clip-handles", s.overlays.clipHandles},
                   {"light-handle", s.overlays.lightHandle},
                   {"planes", s.overlays.planes}};
  if (s.transferFunction)
    j["transfer-function"] = Json::parse(toVolumePropertyJson(*s.transferFunction));
  if (s.time) j["time"] = {{"point", s.time->point}, {"fps", s.time->fps}};
  if (s.comparison) j["comparison"] = comparisonJson(s);
  if (s.reading) j["reading"] = readingJson(*s.reading);
  if (s.fusion) j["fusion"] = fusionJson(*s.fusion, sessionPath);
  if (s.segmentation) j["segmentation"] = segmentationToJson(*s.segmentation);
  try {
    j["measurements"] = Json::parse(s.measurements);
  } catch (const Json::exception& e) {
    throw Error(Error::Kind::Internal,
                std::string("session: the measurements are not JSON (") + e.what() + ")");
  }
  try {
    const Json annotations = Json::parse(s.annotations);
    if (!annotations.empty()) j["annotations"] = annotations;  // older readers: nothing new
  } catch (const Json::exception& e) {
    throw Error(Error::Kind::Internal,
                std::string("session: the annotations are not JSON (") + e.what() + ")");
  }
  return j.dump(2) + "\n";
}

SessionRead sessionFromJson(const std::string& text, const std::string& sessionPath) {
  Json root;
  std::vector<size_t> fields;  // of each object being read, outermost first
  size_t fieldsInAll = 0;
  try {
    // Writing measurements back recurses once per level: a hostile nesting stops here.
    root = Json::parse(text, [&](int depth, Json::parse_event_t event, Json&) {
      if (depth > kMaxDepth)
        throw inputError("session " + sessionPath + ": nested deeper than " +
                         std::to_string(kMaxDepth) + " levels; not a Voxray session");
      if (event == Json::parse_event_t::object_start) fields.push_back(0);
      if (event == Json::parse_event_t::object_end) fields.pop_back();
      if (event == Json::parse_event_t::key && ++fields.back() > kMaxFields)
        throw inputError("session " + sessionPath + ": an object holds more than " +
                         std::to_string(kMaxFields) +
                         " fields; not a Voxray session (or a damaged one)");
      if (event == Json::parse_event_t::key && ++fieldsInAll > kMaxFieldsInAll)
        throw inputError("session " + sessionPath + ": it holds more than " +
                         std::to_string(kMaxFieldsInAll) +
                         " fields in all; not a Voxray session (or a damaged one)");
      return true;
    });
  } catch (const Json::exception& e) {
    throw inputError("session " + sessionPath + ": not a JSON file (" + shown(e.what()) +
                     "); choose a session saved by Voxray");
  }
  if (!root.is_object())
    throw inputError("session " + sessionPath + ": not a Voxray session (no JSON object)");
  Reader r(sessionPath);
  const Json& version = r.require(root, kVersionKey, kVersionKey);
  if (!version.is_number_integer() || version.get<long long>() < 1)
    r.fail(kVersionKey, "must be a whole number from 1");
  if (version.get<long long>() > kSessionVersion)
    throw inputError("session " + sessionPath + ": written by a newer Voxray (session version " +
                     version.dump() + "; this one reads up to " + std::to_string(kSessionVersion) +
                     "); open it with a newer Voxray");
  r.warnUnknown(root, "",
                {kVersionKey, "input", "render", "quality", "slices", "layout", "overlays",
                 "transfer-function", "measurements", "annotations", "segmentation", "time",
                 "comparison", "reading", "fusion"});
  SessionRead out;
  Session& s = out.session;
  readInput(r, root, sessionPath, out);
  readRender(r, root, s.render);

  const Json& quality = r.object(root, "quality", "quality");
  r.warnUnknown(quality, "quality.", {"preset", "resolution"});
  s.qualityPreset = r.text(r.require(quality, "quality.preset", "preset"), "quality.preset");
  if (!s.qualityPreset.empty()) {
    try {
      s.qualityPreset = findQualityPreset(s.qualityPreset).name;
    } catch (const Error& e) {
      r.fail("quality.preset", std::string("is wrong: ") + e.what());
    }
  }
  auto res =
      r.wholes(r.require(quality, "quality.resolution", "resolution"), "quality.resolution", 2);
  if (res[0] < 0 || res[1] < 0 || res[0] > 16384 || res[1] > 16384 ||
      (res[0] == 0) != (res[1] == 0))
    r.fail("quality.resolution", "must be [0, 0] (the view's size) or 1 ... 16384 each");
  s.resolution = {res[0], res[1]};

  const Json& slices = r.object(root, "slices", "slices");
  r.warnUnknown(slices, "slices.",
                {"window-width", "window-level", "crosshair", "interp", "centre", "views"});
  s.window.width =
      r.number(r.require(slices, "slices.window-width", "window-width"), "slices.window-width");
  if (!(s.window.width > 0.0)) r.fail("slices.window-width", "must be greater than 0");
  s.window.level =
      r.number(r.require(slices, "slices.window-level", "window-level"), "slices.window-level");
  auto c = r.wholes(r.require(slices, "slices.crosshair", "crosshair"), "slices.crosshair", 3);
  s.crosshair = {c[0], c[1], c[2]};
  try {
    s.sliceInterp =
        parseInterp(r.text(r.require(slices, "slices.interp", "interp"), "slices.interp"));
  } catch (const Error& e) {
    r.fail("slices.interp", std::string("is wrong: ") + e.what());
  }
  readViews(r, slices, s);

  s.layout = r.text(r.require(root, "layout", "layout"), "layout");
  const auto& layouts = sessionLayouts();
  if (std::find(layouts.begin(), layouts.end(), s.layout) == layouts.end())
    r.fail("layout", "must be one of grid, 3d, axial, coronal, sagittal");
  readOverlays(r, root, s.overlays);
  readReading(r, root, s);
  readFusion(r, root, sessionPath, out);
  if (root.contains("transfer-function")) {
    try {
      s.transferFunction =
          parseVolumePropertyJson(root.at("transfer-function").dump(), "transfer-function");
    } catch (const Error& e) {
      std::string what = e.what();
      const std::string origin = "transfer-function: ";
      if (what.rfind(origin, 0) == 0) what.erase(0, origin.size());
      r.fail("transfer-function", "is wrong: " + what);
    }
  }
  if (root.contains("time")) {
    const Json& time = r.object(root, "time", "time");
    r.warnUnknown(time, "time.", {"point", "fps"});
    Session::Time t;
    const Json& point = r.require(time, "time.point", "point");
    if (!point.is_number_integer() || point.get<long long>() < 0 || point.get<long long>() > 100000)
      r.fail("time.point", "must be a whole number 0 ... 100000 (a time point, 0-based)");
    t.point = point.get<int>();
    t.fps = r.number(r.require(time, "time.fps", "fps"), "time.fps");
    if (!(t.fps >= 0.5 && t.fps <= 60.0))
      r.fail("time.fps", "must be 0.5 ... 60 frames per second");
    s.time = t;
  }
  readComparison(r, root, s);
  if (root.contains("measurements")) {
    if (!root.at("measurements").is_array()) r.fail("measurements", "must be an array [ ... ]");
    s.measurements = root.at("measurements").dump();
  }
  if (root.contains("annotations")) {
    if (!root.at("annotations").is_array()) r.fail("annotations", "must be an array [ ... ]");
    s.annotations = root.at("annotations").dump();
  }
  if (root.contains("segmentation")) {
    try {
      s.segmentation = segmentationFromJson(root.at("segmentation"));
    } catch (const Error& e) {
      r.fail("segmentation", std::string("is wrong: ") + e.what());
    }
  }
  out.warnings = r.allWarnings();
  return out;
}

}  // namespace voxray
