#include "session.h"

#include "comparison_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>

#include <nlohmann/json.hpp>

#include "fusion.h"
#include "segmentation_json.h"
#include "voxray/engine/input_flags.h"
#include "voxray/engine/quality.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

// Ordered: a session reads top to bottom as written, and measurements keep their key order.
using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

constexpr const char* kVersionKey = "voxray-session";
constexpr std::array<const char*, 3> kViewNames = {"axial", "coronal", "sagittal"};
constexpr int kMaxDepth = 256;
// A session object holds tens of fields; an object with more is not one, and reading it would
// not end soon (ordered_json compares each key with every earlier one of its object: 300,000
// keys took minutes, 2,000 objects of 1,000 keys 10 s). Unknown fields are listed up to
// kListedUnknown lines.
constexpr size_t kMaxFields = 1000, kMaxFieldsInAll = 100000;
constexpr size_t kListedUnknown = 20;

// TEXT as a message may show it: bytes that are not UTF-8 become U+FFFD and control
// characters \u escapes (the JSON library's own string escaping), so a hostile file puts no
// raw bytes or terminal escapes into an error.
std::string shown(const std::string& text) {
  const std::string quoted = Json(text).dump(-1, ' ', false, Json::error_handler_t::replace);
  return quoted.substr(1, quoted.size() - 2);
}

// Reads one session's JSON, naming the file and the field in every error, and collecting
// the warnings about fields it ignores or misses.
class Reader {
 public:
  explicit Reader(std::string sessionPath) : path_(std::move(sessionPath)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw inputError("session " + path_ + ": field '" + shown(field) + "' " + shown(what));
  }

  // OBJ's KEY (FIELD names it); a missing one is an error.
  const Json& require(const Json& obj, const std::string& field, const std::string& key) const {
    auto it = obj.find(key);
    if (it == obj.end())
      throw inputError("session " + path_ + ": the required field '" + field +
                       "' is missing; the file is damaged or not a Voxray session (save the "
                       "session again)");
    return *it;
  }
  const Json& object(const Json& obj, const std::string& field, const std::string& key) const {
    const Json& v = require(obj, field, key);
    if (!v.is_object()) fail(field, "must be an object { ... }");
    return v;
  }
  std::string text(const Json& v, const std::string& field) const {
    if (!v.is_string()) fail(field, "must be a string");
    return v.get<std::string>();
  }
  double number(const Json& v, const std::string& field) const {
    if (!v.is_number()) fail(field, "must be a number");
    return v.get<double>();
  }
  std::vector<int> wholes(const Json& v, const std::string& field, size_t count) const {
    const std::string want = "must be an array of " + std::to_string(count) + " whole numbers";
    if (!v.is_array() || v.size() != count) fail(field, want);
    std::vector<int> out;
    for (const Json& n : v) {
      if (!n.is_number_integer()) fail(field, want);
      out.push_back(n.get<int>());
    }
    return out;
  }
  std::vector<double> numbers(const Json& v, const std::string& field, size_t count) const {
    const std::string want = "must be an array of " + std::to_string(count) + " numbers";
    if (!v.is_array() || v.size() != count) fail(field, want);
    std::vector<double> out;
    for (const Json& n : v) out.push_back(number(n, field));
    return out;
  }
  // A declared value as its text: strings as they are, numbers and booleans as a hand
  // editor would expect them to read.
  std::string valueText(const Json& v, const std::string& field) const {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "on" : "off";
    if (v.is_number()) return v.dump();
    fail(field, "must be a string, a number or true/false");
  }
  // Keys of OBJ (under PARENT) not in KNOWN: warned about, ignored.
  void warnUnknown(const Json& obj, const std::string& parent,
                   const std::vector<std::string>& known) {
    for (const auto& item : obj.items())
      if (std::find(known.begin(), known.end(), item.key()) == known.end())
        unknown(parent + item.key());
  }
  void unknown(const std::string& field) {
    if (++unknown_ <= kListedUnknown)
      warnings.push_back("unknown field '" + shown(field) + "' ignored");
  }
  // The warnings, with a line for the unknown fields beyond those listed.
  std::vector<std::string> allWarnings() {
    if (unknown_ > kListedUnknown)
      warnings.push_back("and " + std::to_string(unknown_ - kListedUnknown) +
                         " more unknown fields ignored");
    return std::move(warnings);
  }

  std::vector<std::string> warnings;

 private:
  size_t unknown_ = 0;
  std::string path_;
};

fs::path folderOf(const std::string& sessionPath) {
  return fs::absolute(fs::path(sessionPath)).lexically_normal().parent_path();
}

// PATH absolute and normal, without a trailing separator.
fs::path normalAbsolute(const std::string& path) {
  fs::path p = fs::absolute(fs::path(path)).lexically_normal();
  return p.has_filename() ? p : p.parent_path();
}

Json inputJson(const SessionInput& in, const std::string& sessionPath) {
  Json j;
  if (in.path.empty()) {
    j["path"] = "";
  } else {
    const fs::path absolute = normalAbsolute(in.path), folder = folderOf(sessionPath);
    // Relative when the two share a folder below the root ("/data/study" beside
    // "/data/sessions"): such trees move together; "../../../work/..." would not.
    auto top = [](const fs::path& p) {
      return std::next(p.begin()) == p.end() ? fs::path() : *std::next(p.begin());
    };
    const fs::path relative = top(absolute) == top(folder) && !top(folder).empty()
                                  ? absolute.lexically_relative(folder)
                                  : fs::path();
    j["path"] = (relative.empty() ? absolute : relative).string();
    j["absolute-path"] = absolute.string();
  }
  j["flags"] = Json::object();
  for (const auto& [key, value] : in.flags) j["flags"][key] = value;
  return j;
}

// An input object (the study's "input", the overlay's "fusion.input"), FIELD naming it: its
// path resolved beside the session first (a folder moved with its session), then where it was
// saved; MISSING lists the paths tried when it is at none.
void readInputObject(Reader& r, const Json& in, const std::string& field,
                     const std::string& sessionPath, SessionInput& out,
                     std::vector<std::string>& missing) {
  r.warnUnknown(in, field + ".", {"path", "absolute-path", "flags"});
  const std::string written = r.text(r.require(in, field + ".path", "path"), field + ".path");
  if (in.contains("flags")) {
    const Json& flags = r.object(in, field + ".flags", "flags");
    for (const auto& item : flags.items()) {
      const std::string flag = field + ".flags." + item.key();
      try {
        findInputFlagSpec(item.key());
      } catch (const Error&) {
        r.unknown(flag);
        continue;
      }
      out.flags[item.key()] = r.valueText(item.value(), flag);
    }
    try {
      loadOptionsFromFlags(out.flags);
    } catch (const Error& e) {
      r.fail(field + ".flags", std::string("is wrong: ") + e.what());
    }
  }
  if (written.empty()) return;  // the embedded head phantom
  std::vector<fs::path> candidates;
  const fs::path p(written);
  candidates.push_back(p.is_absolute() ? p : (folderOf(sessionPath) / p).lexically_normal());
  if (in.contains("absolute-path")) {
    fs::path a(r.text(in.at("absolute-path"), field + ".absolute-path"));
    if (a != candidates.front()) candidates.push_back(a);
  }
  std::error_code ec;
  for (const fs::path& c : candidates)
    if (fs::exists(c, ec)) {
      out.path = c.string();
      return;
    }
  out.path = candidates.front().string();
  for (const fs::path& c : candidates) missing.push_back(c.string());
}

void readInput(Reader& r, const Json& root, const std::string& sessionPath, SessionRead& out) {
  readInputObject(r, r.object(root, "input", "input"), "input", sessionPath, out.session.input,
                  out.missingInput);
}

Json readingJson(const ReadingLayout& l) {
  Json views = Json::object();
  for (const PlacedView& p : l.placed) {
    Json v = Json::object();
    if (!p.series.empty()) v["series"] = p.series;
    if (!p.uid.empty()) v["uid"] = p.uid;
    if (!p.description.empty()) v["description"] = p.description;
    if (!p.note.empty()) v["note"] = p.note;
    views[gridViewName(p.view)] = v;
  }
  Json j = {{"layout", layoutName(l.layout)}};
  if (!views.empty()) j["views"] = views;
  return j;
}

// The prior's 3D camera (compare): every field required, in the ranges the camera takes.
CameraParams readPriorCamera(Reader& r, const Json& comparison) {
  const std::string f = "comparison.prior-camera";
  const Json& j = r.object(comparison, f, "prior-camera");
  r.warnUnknown(
      j, f + ".",
      {"azimuth-deg", "elevation-deg", "zoom", "distance-mm", "pan-mm", "projection", "fov-deg"});
  CameraParams c;
  auto number = [&](const char* key) {
    return r.number(r.require(j, f + "." + key, key), f + "." + key);
  };
  c.azimuthDeg = number("azimuth-deg");
  c.elevationDeg = number("elevation-deg");
  c.zoom = number("zoom");
  c.distanceMm = number("distance-mm");
  c.fovDeg = number("fov-deg");
  if (!(c.zoom > 0.0)) r.fail(f + ".zoom", "must be above 0");
  if (!(c.distanceMm >= 0.0)) r.fail(f + ".distance-mm", "must be 0 (frame the volume) or more");
  if (!(c.fovDeg > 0.0 && c.fovDeg < 180.0)) r.fail(f + ".fov-deg", "must be 0 ... 180 degrees");
  const Json& pan = r.require(j, f + ".pan-mm", "pan-mm");
  if (!pan.is_array() || pan.size() != 2 || !pan[0].is_number() || !pan[1].is_number())
    r.fail(f + ".pan-mm", "must be two numbers (mm)");
  c.panMm = {pan[0].get<double>(), pan[1].get<double>()};
  const std::string p = r.text(r.require(j, f + ".projection", "projection"), f + ".projection");
  if (p != "perspective" && p != "orthographic")
    r.fail(f + ".projection", "must be perspective or orthographic");
  c.projection = p == "orthographic" ? Projection::Orthographic : Projection::Perspective;
  return c;
}

void readReading(Reader& r, const Json& root, Session& s) {
  if (!root.contains("reading")) return;
  const Json& reading = r.object(root, "reading", "reading");
  r.warnUnknown(reading, "reading.", {"layout", "views"});
  ReadingLayout l;
  const std::string name = r.text(r.require(reading, "reading.layout", "layout"), "reading.layout");
  const auto layout = parseLayout(name);
  if (!layout) r.fail("reading.layout", "must be one of 1x1, 1x2, 2x2, 1+3, mpr+3d, 3d");
  l.layout = *layout;
  if (reading.contains("views")) {
    const Json& views = r.object(reading, "reading.views", "views");
    for (const auto& item : views.items()) {
      const std::string field = "reading.views." + item.key();
      const auto view = parseGridView(item.key());
      if (!view) {
        r.unknown(field);
        continue;
      }
      const Json& v = r.object(views, field, item.key());
      r.warnUnknown(v, field + ".", {"series", "uid", "description", "note"});
      PlacedView p;
      p.view = *view;
      if (v.contains("series")) p.series = r.text(v.at("series"), field + ".series");
      if (v.contains("uid")) p.uid = r.text(v.at("uid"), field + ".uid");
      if (v.contains("description"))
        p.description = r.text(v.at("description"), field + ".description");
      if (v.contains("note")) p.note = r.text(v.at("note"), field + ".note");
      if (p.series.empty() && p.note.empty()) p.note = "left empty when the session was saved";
      l.placed.push_back(p);
    }
  }
  s.reading = l;
}

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

void readRender(Reader& r, const Json& root, RenderParams& p) {
  const Json& render = r.object(root, "render", "render");
  std::vector<std::string> known;
  // Declaration order: "light" (which fixes the light) before "light-follows-camera".
  for (const auto& spec : renderParamSpecs()) {
    known.push_back(spec.key);
    const std::string field = "render." + spec.key;
    auto it = render.find(spec.key);
    if (it == render.end()) {
      r.warnings.push_back("field '" + field + "' missing: left at its default (" + spec.format(p) +
                           ")");
      continue;
    }
    try {
      spec.parse(p, r.valueText(*it, field));
    } catch (const Error& e) {
      r.fail(field, std::string("is wrong: ") + e.what());
    }
  }
  r.warnUnknown(render, "render.", known);
}

// The views that are turned or thick, by name; absent views are acquisition planes, thin.
Json viewsJson(const std::array<SessionView, 3>& views) {
  Json j = Json::object();
  for (size_t o = 0; o < views.size(); ++o) {
    const SessionView& v = views[o];
    if (v.rotation == glm::dmat3(1.0) && v.slab.thicknessMm == 0.0) continue;
    Json rows = Json::array();  // row by row, as the matrix is written on paper
    for (int r = 0; r < 3; ++r)
      rows.push_back({v.rotation[0][r], v.rotation[1][r], v.rotation[2][r]});
    j[kViewNames[o]] = {
        {"rotation", rows}, {"slab-mm", v.slab.thicknessMm}, {"slab-mode", toString(v.slab.mode)}};
  }
  return j;
}

void readViews(Reader& r, const Json& slices, Session& s) {
  if (!slices.contains("views")) return;
  const Json& views = r.object(slices, "slices.views", "views");
  r.warnUnknown(views, "slices.views.", {kViewNames.begin(), kViewNames.end()});
  for (size_t o = 0; o < kViewNames.size(); ++o) {
    if (!views.contains(kViewNames[o])) continue;
    const std::string field = std::string("slices.views.") + kViewNames[o];
    const Json& view = r.object(views, field, kViewNames[o]);
    r.warnUnknown(view, field + ".", {"rotation", "slab-mm", "slab-mode"});
    SessionView& v = s.views[o];
    if (view.contains("rotation")) {
      const Json& rows = view.at("rotation");
      const std::string want = "must be 3 rows of 3 numbers: a rotation";
      if (!rows.is_array() || rows.size() != 3) r.fail(field + ".rotation", want);
      for (int row = 0; row < 3; ++row) {
        auto n = r.numbers(rows.at(size_t(row)), field + ".rotation", 3);
        for (int col = 0; col < 3; ++col) v.rotation[col][row] = n[size_t(col)];
      }
      // A hand-edited matrix that is no rotation would shear the planes: refuse it.
      const glm::dmat3 error = glm::transpose(v.rotation) * v.rotation - glm::dmat3(1.0);
      double worst = 0.0;
      for (int c = 0; c < 3; ++c)
        for (int rr = 0; rr < 3; ++rr) worst = std::max(worst, std::abs(error[c][rr]));
      if (!(worst < 1e-6) || glm::determinant(v.rotation) < 0.0)
        r.fail(field + ".rotation", "is not a rotation (orthonormal, determinant 1)");
    }
    if (view.contains("slab-mm")) {
      v.slab.thicknessMm = r.number(view.at("slab-mm"), field + ".slab-mm");
      if (!(v.slab.thicknessMm >= 0.0) || !std::isfinite(v.slab.thicknessMm))
        r.fail(field + ".slab-mm", "must be 0 (a thin slice) or more millimetres");
    }
    if (view.contains("slab-mode")) {
      try {
        v.slab.mode = parseSlabMode(r.text(view.at("slab-mode"), field + ".slab-mode"));
      } catch (const Error& e) {
        r.fail(field + ".slab-mode", std::string("is wrong: ") + e.what());
      }
    }
  }
  if (slices.contains("centre")) {
    auto c = r.numbers(slices.at("centre"), "slices.centre", 3);
    s.centre = glm::dvec3(c[0], c[1], c[2]);
  }
}

// Sessions before the overlays were saved lack the object, or a key of it: the defaults.
void readOverlays(Reader& r, const Json& root, ViewOverlays& o) {
  if (!root.contains("overlays")) return;
  const Json& overlays = r.object(root, "overlays", "overlays");
  r.warnUnknown(overlays, "overlays.", {"clip-handles", "light-handle", "planes"});
  const std::pair<const char*, bool ViewOverlays::*> fields[] = {
      {"clip-handles", &ViewOverlays::clipHandles},
      {"light-handle", &ViewOverlays::lightHandle},
      {"planes", &ViewOverlays::planes}};
  for (const auto& [key, field] : fields) {
    if (!overlays.contains(key)) continue;
    const Json& v = overlays.at(key);
    if (!v.is_boolean()) r.fail(std::string("overlays.") + key, "must be true or false");
    o.*field = v.get<bool>();
  }
}

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
  if (s.comparison) {
    Json c = {{"prior", s.comparison->priorPath},
              {"prior-time-point", s.comparison->priorTimePoint}};
    if (!s.comparison->priorSeries.empty()) c["series"] = s.comparison->priorSeries;
    if (!s.comparison->linkLook) c["link-look"] = false;
    if (const auto& cam = s.comparison->priorCamera)
      c["prior-camera"] = {
          {"azimuth-deg", cam->azimuthDeg},
          {"elevation-deg", cam->elevationDeg},
          {"zoom", cam->zoom},
          {"distance-mm", cam->distanceMm},
          {"pan-mm", {cam->panMm.x, cam->panMm.y}},
          {"projection",
           cam->projection == Projection::Orthographic ? "orthographic" : "perspective"},
          {"fov-deg", cam->fovDeg}};
    if (s.comparison->movingToFixed) {
      Json rows = Json::array();  // row by row, as the matrix is written on paper
      for (int row = 0; row < 4; ++row) {
        Json r = Json::array();
        for (int col = 0; col < 4; ++col) r.push_back((*s.comparison->movingToFixed)[col][row]);
        rows.push_back(r);
      }
      c["moving-to-fixed"] = rows;
    }
    j["comparison"] = c;
  }
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
  if (root.contains("comparison")) {
    const Json& c = r.object(root, "comparison", "comparison");
    r.warnUnknown(
        c, "comparison.",
        {"prior", "series", "moving-to-fixed", "link-look", "prior-camera", "prior-time-point"});
    Session::Comparison out;
    out.priorPath = r.text(r.require(c, "comparison.prior", "prior"), "comparison.prior");
    out.priorTimePoint = readTimePoint(r, c, "prior-time-point", "comparison.prior-time-point");
    if (c.contains("series")) out.priorSeries = r.text(c.at("series"), "comparison.series");
    if (c.contains("link-look")) {
      if (!c.at("link-look").is_boolean()) r.fail("comparison.link-look", "must be true or false");
      out.linkLook = c.at("link-look").get<bool>();
    }
    if (c.contains("prior-camera")) out.priorCamera = readPriorCamera(r, c);
    if (c.contains("moving-to-fixed")) {
      const std::string want =
          "must be 4 rows of 4 numbers: a rotation and a translation in mm, last row 0 0 0 1";
      const Json& rows = c.at("moving-to-fixed");
      if (!rows.is_array() || rows.size() != 4) r.fail("comparison.moving-to-fixed", want);
      glm::dmat4 m(1.0);
      for (int row = 0; row < 4; ++row) {
        const Json& values = rows.at(size_t(row));
        if (!values.is_array() || values.size() != 4) r.fail("comparison.moving-to-fixed", want);
        for (int col = 0; col < 4; ++col) {
          if (!values.at(size_t(col)).is_number()) r.fail("comparison.moving-to-fixed", want);
          m[col][row] = values.at(size_t(col)).get<double>();
        }
      }
      if (!isRigid(m)) r.fail("comparison.moving-to-fixed", want + " (this one is not rigid)");
      out.movingToFixed = m;
    }
    s.comparison = out;
  }
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

std::string movedDataMessage(const std::string& sessionPath, const std::vector<std::string>& tried,
                             const std::string& fix) {
  std::string where;
  for (size_t i = 0; i < tried.size(); ++i)
    where += (i ? (i + 1 == tried.size() ? " nor at " : ", ") : "") + tried[i];
  return "session " + sessionPath + ": its data is missing (not at " + where +
         "); the data moved or was deleted. " + fix;
}

}  // namespace voxray
