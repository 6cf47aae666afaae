// Session files (issue 13): every field round-trips exactly, paths are stored relative to
// the session, damaged and newer files say which field is wrong, and nothing is replaced
// without being allowed to.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

#include "session.h"
#include "session_state.h"
#include "tf_editor_model.h"
#include "voxray/io/error.h"

using namespace voxray;
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

// A fresh folder under $TMPDIR, removed at the end.
struct Scratch {
  fs::path root;
  Scratch() {
    std::random_device seed;
    root = fs::temp_directory_path() / ("voxray-session-test-" + std::to_string(seed()));
    fs::create_directories(root);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
  std::string touch(const std::string& relative) const {
    fs::create_directories((root / relative).parent_path());
    std::ofstream(root / relative) << "x";
    return (root / relative).string();
  }
};

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every render parameter away from its default, as the declaration's text, with values ten
// significant digits would not keep (a dragged camera): 1/3, 2/3, 1/7, 100/3.
const std::map<std::string, std::string> kUnusual = {
    {"size", "641x479"},
    {"mode", "dvr"},
    {"preset", "CT-Bone"},
    {"tf", "-100.5:0.1:0.2:0.3:0,300.25:1:0.9:0.8:0.05"},
    {"opacity-unit", "0.7071067811865476"},
    {"gradient-opacity", "0:0,33.333333333333336:0.25,150.5:1"},
    {"tf2d",
     "rect:-100.5,300.25,0,33.333333333333336,0.1,0.2,0.3,0.5,0.25;"
     "tri:200,1400,50,800,1,0.9,0.8,0.4,0;gmax:1000.5"},
    {"preset-shift", "-123.456789012345"},
    {"iso", "150,2000"},
    {"gradient", "sobel"},
    {"interp", "nearest"},
    {"step", "0.3"},
    {"refine", "7"},
    {"shading", "off"},
    {"opacity-correction", "off"},
    {"jitter", "on"},
    {"adaptive", "0.05"},
    {"preintegrate", "on"},
    {"adaptive-image", "12.5,2"},
    {"segment-mask", "hide:2,7"},
    {"segment-blend", "0.35"},
    {"segment-tf", "3:-1000:1:0.5:0.25:0,0.1:1:0.5:0.25:0.333;7:-5:0:0:1:1"},
    {"early-termination", "0.95"},
    {"window", "1500,-600"},
    {"azimuth", "0.3333333333333333"},
    {"elevation", "-21.234567890123"},
    {"zoom", "0.6666666666666666"},
    {"distance", "812.5"},
    {"pan", "12.3456789012345,-0.1"},
    {"projection", "orthographic"},
    {"fov", "45"},
    {"clip", "0.1,0.9,0.2,0.8,0.14285714285714285,0.7"},
    {"light", "33.333333333333336,-5.5,20"},
    {"light-follows-camera", "off"},
    {"ambient", "0.2"},
    {"diffuse", "0.6"},
    {"specular", "0.4"},
    {"shininess", "64"},
    {"lighting", "shadows"},
    {"surface-color", "0.5,0.25,0.125"},
    {"background", "0.1,0.2,0.3"}};

Session unusualSession() {
  Session s;
  for (const auto& spec : renderParamSpecs()) {  // a new parameter needs a value above
    EXPECT_TRUE(kUnusual.count(spec.key)) << "no unusual value for " << spec.key;
    if (kUnusual.count(spec.key)) spec.parse(s.render, kUnusual.at(spec.key));
  }
  s.qualityPreset = "reference";
  s.resolution = {800, 600};
  s.window = {350.5, 45.25};
  s.crosshair = {12, 34, 56};
  s.sliceInterp = Interp::Nearest;
  s.layout = "coronal";
  s.measurements = R"([{"z":1,"kind":"distance","points":[[1.5,2,3],[4,5,6]],"mm":12.25}])";
  return s;
}

Json jsonOf(const Session& s, const std::string& sessionPath) {
  return Json::parse(sessionToJson(s, sessionPath));
}

// The message of the Error that reading J throws ("" when it reads).
std::string readJsonError(const Json& j) {
  try {
    sessionFromJson(j.dump(), "s.json");
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Session, EveryFieldRoundTripsExactly) {
  Scratch dir;
  Session s = unusualSession();
  s.input.path = dir.touch("data/CThead");
  s.input.flags = {{"raw-dims", "256,256"},  {"raw-type", "i16"}, {"raw-endian", "big"},
                   {"raw-spacing", "1,1,2"}, {"raw-axes", "LPI"}, {"raw-rescale", "1,-1024"}};
  const RenderParams defaults;
  for (const auto& spec : renderParamSpecs())  // each parameter is tested away from its default
    EXPECT_NE(spec.format(s.render), spec.format(defaults)) << spec.key;

  const std::string file = (dir.root / "a.json").string();
  writeSessionFile(file, s, false);
  const SessionRead read = readSessionFile(file);
  EXPECT_TRUE(read.warnings.empty()) << read.warnings.front();
  EXPECT_TRUE(read.missingInput.empty());
  const Session& r = read.session;
  for (const auto& spec : renderParamSpecs())
    EXPECT_EQ(spec.format(r.render), spec.format(s.render)) << spec.key;
  EXPECT_EQ(toText(r.render), toText(s.render));
  // Exactly, not to ten digits: a reopened session renders the frame it was saved from.
  EXPECT_EQ(r.render.camera.azimuthDeg, 1.0 / 3.0);
  EXPECT_EQ(r.render.camera.zoom, 2.0 / 3.0);
  EXPECT_EQ(r.render.camera.elevationDeg, -21.234567890123);
  EXPECT_EQ(r.render.clip.lo.z, 1.0 / 7.0);
  EXPECT_EQ(r.render.light.position.x, 100.0 / 3.0);
  EXPECT_FALSE(r.render.light.followCamera);
  EXPECT_EQ(r.render.presetShiftHu, -123.456789012345);
  EXPECT_EQ(r.render.camera.panMm.x, 12.3456789012345);
  EXPECT_EQ(r.input.path, s.input.path);
  EXPECT_EQ(r.input.flags, s.input.flags);
  EXPECT_EQ(r.qualityPreset, "reference");
  EXPECT_EQ(r.resolution, glm::ivec2(800, 600));
  EXPECT_EQ(r.window.width, 350.5);
  EXPECT_EQ(r.window.level, 45.25);
  EXPECT_EQ(r.crosshair, glm::ivec3(12, 34, 56));
  EXPECT_EQ(r.sliceInterp, Interp::Nearest);
  EXPECT_EQ(r.layout, "coronal");
  EXPECT_EQ(r.measurements, s.measurements);  // untouched, key order included
  // The phantom (no path) and a custom quality round-trip too.
  Session phantom;
  phantom.qualityPreset = "";
  const std::string file2 = (dir.root / "phantom.json").string();
  writeSessionFile(file2, phantom, false);
  EXPECT_EQ(readSessionFile(file2).session.input.path, "");
  EXPECT_EQ(readSessionFile(file2).session.qualityPreset, "");
}

TEST(Session, InputIsStoredRelativeToTheSessionAndFollowsAMovedFolder) {
  Scratch dir;
  Session s;
  s.input.path = dir.touch("study/data/volume.raw");
  const std::string file = (dir.root / "study/sessions/a.json").string();
  fs::create_directories(dir.root / "study/sessions");
  writeSessionFile(file, s, false);
  const Json j = Json::parse(readText(file));
  EXPECT_EQ(j["input"]["path"], "../data/volume.raw");
  EXPECT_EQ(j["input"]["absolute-path"], s.input.path);

  // Nothing in common below the root: the absolute path (a "../../.." path would not move).
  Session far;
  far.input.path = "/voxray-elsewhere/data/volume.raw";
  EXPECT_EQ(jsonOf(far, (dir.root / "a.json").string())["input"]["path"], far.input.path);

  // The whole study folder moved (another machine): found beside the session.
  fs::rename(dir.root / "study", dir.root / "moved");
  SessionRead read = readSessionFile((dir.root / "moved/sessions/a.json").string());
  EXPECT_TRUE(read.missingInput.empty());
  EXPECT_EQ(read.session.input.path, (dir.root / "moved/data/volume.raw").string());

  // Only the session moved: the absolute path of the save is the fallback.
  fs::rename(dir.root / "moved", dir.root / "study");
  fs::create_directories(dir.root / "elsewhere");
  fs::copy_file(file, dir.root / "elsewhere/a.json");
  read = readSessionFile((dir.root / "elsewhere/a.json").string());
  EXPECT_TRUE(read.missingInput.empty());
  EXPECT_EQ(read.session.input.path, s.input.path);
}

TEST(Session, MovedDataIsNamedWithBothPlacesTried) {
  Scratch dir;
  Session s;
  s.input.path = dir.touch("data/volume.raw");
  const std::string file = (dir.root / "a.json").string();
  writeSessionFile(file, s, false);
  fs::remove_all(dir.root / "data");
  const SessionRead read = readSessionFile(file);
  ASSERT_EQ(read.missingInput.size(), 1u);  // relative and absolute are the same place here
  EXPECT_EQ(read.missingInput[0], (dir.root / "data/volume.raw").string());
  const std::string m = movedDataMessage(file, read.missingInput, "Give its new location.");
  EXPECT_NE(m.find((dir.root / "data/volume.raw").string()), std::string::npos) << m;
  EXPECT_NE(m.find("data is missing"), std::string::npos) << m;
  EXPECT_NE(m.find("Give its new location."), std::string::npos) << m;

  // Session elsewhere: two places tried, both named.
  fs::create_directories(dir.root / "other");
  fs::copy_file(file, dir.root / "other/a.json");
  const SessionRead other = readSessionFile((dir.root / "other/a.json").string());
  ASSERT_EQ(other.missingInput.size(), 2u);
  EXPECT_EQ(other.missingInput[0], (dir.root / "other/data/volume.raw").string());
  EXPECT_EQ(other.missingInput[1], (dir.root / "data/volume.raw").string());
}

TEST(Session, UnknownFieldsAreListedAndIgnored) {
  Json j = jsonOf(Session{}, "s.json");
  j["colour-scheme"] = "night";
  j["render"]["hologram"] = "on";
  j["slices"]["ruler"] = true;
  j["input"]["flags"]["raw-gamma"] = "2.2";
  j["render"].erase("jitter");  // an older version's session: the default is used
  const SessionRead read = sessionFromJson(j.dump(), "s.json");
  std::string all;
  for (const auto& w : read.warnings) all += w + "\n";
  EXPECT_EQ(read.warnings.size(), 5u) << all;
  for (const char* field :
       {"'colour-scheme'", "'render.hologram'", "'slices.ruler'", "'input.flags.raw-gamma'"})
    EXPECT_NE(all.find(std::string("unknown field ") + field + " ignored"), std::string::npos)
        << field << "\n"
        << all;
  EXPECT_NE(all.find("'render.jitter' missing: left at its default (off)"), std::string::npos)
      << all;
  EXPECT_FALSE(read.session.render.jitter);
  EXPECT_TRUE(read.session.input.flags.empty());
}

TEST(Session, MissingOrWrongFieldsAreErrorsNamingTheField) {
  const Json good = jsonOf(Session{}, "s.json");
  EXPECT_EQ(readJsonError(good), "");
  auto without = [&](const std::string& section, const std::string& key) {
    Json j = good;
    (key.empty() ? j : j[section]).erase(key.empty() ? section : key);
    return readJsonError(j);
  };
  EXPECT_NE(without("render", "").find("s.json: the required field 'render' is missing"),
            std::string::npos);
  EXPECT_NE(without("voxray-session", "").find("'voxray-session' is missing"), std::string::npos);
  EXPECT_NE(without("input", "path").find("'input.path' is missing"), std::string::npos);
  EXPECT_NE(without("slices", "crosshair").find("'slices.crosshair' is missing"),
            std::string::npos);
  EXPECT_NE(without("quality", "preset").find("'quality.preset' is missing"), std::string::npos);

  auto with = [&](const std::string& section, const std::string& key, const Json& value) {
    Json j = good;
    (key.empty() ? j[section] : j[section][key]) = value;
    return readJsonError(j);
  };
  EXPECT_NE(with("slices", "crosshair", "1,2,3")
                .find("field 'slices.crosshair' must be an array "
                      "of 3 whole numbers"),
            std::string::npos);
  EXPECT_NE(with("render", "azimuth", "left")
                .find("field 'render.azimuth' is wrong: --azimuth: "
                      "'left' is not a number"),
            std::string::npos);
  EXPECT_NE(with("render", "", Json::array()).find("field 'render' must be an object"),
            std::string::npos);
  EXPECT_NE(with("quality", "preset", "ultra").find("field 'quality.preset' is wrong"),
            std::string::npos);
  EXPECT_NE(with("layout", "", "3x3").find("field 'layout' must be one of grid"),
            std::string::npos);
  EXPECT_NE(with("input", "flags", Json{{"raw-type", "i16"}}).find("field 'input.flags' is wrong"),
            std::string::npos);
  // Numbers and booleans where the declaration's text is expected read as a hand editor means.
  Json hand = good;
  hand["render"]["azimuth"] = 30;
  hand["render"]["jitter"] = true;
  const Session read = sessionFromJson(hand.dump(), "s.json").session;
  EXPECT_EQ(read.render.camera.azimuthDeg, 30.0);
  EXPECT_TRUE(read.render.jitter);

  EXPECT_NE(readJsonError(Json::parse("[1, 2]")).find("not a Voxray session"), std::string::npos);
  // Measurements nested 100,000 deep (hostile input) are refused, not written back recursively.
  std::string deep = good.dump();
  deep.replace(deep.find("\"measurements\":[]"), 17,
               "\"measurements\":" + std::string(100000, '[') + std::string(100000, ']'));
  try {
    sessionFromJson(deep, "s.json");
    ADD_FAILURE() << "100,000 levels read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nested deeper than 256 levels"), std::string::npos)
        << e.what();
  }
  try {
    sessionFromJson("{\"voxray-session\": 1,", "s.json");
    ADD_FAILURE() << "truncated JSON read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("s.json: not a JSON file"), std::string::npos);
  }
}

TEST(Session, ANewerVersionSaysSo) {
  Json j = jsonOf(Session{}, "s.json");
  j["voxray-session"] = kSessionVersion + 1;
  EXPECT_NE(readJsonError(j).find("written by a newer Voxray (session version " +
                                  std::to_string(kSessionVersion + 1) + "; this one reads up to " +
                                  std::to_string(kSessionVersion) + ")"),
            std::string::npos);
  j["voxray-session"] = "one";
  EXPECT_NE(readJsonError(j).find("'voxray-session' must be a whole number"), std::string::npos);
}

TEST(Session, AnExistingFileIsReplacedOnlyWhenAllowed) {
  Scratch dir;
  const std::string file = dir.touch("a.json");
  Session s;
  try {
    writeSessionFile(file, s, false);
    ADD_FAILURE() << "replaced without being allowed";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Output);
    EXPECT_NE(std::string(e.what()).find("exists and is kept"), std::string::npos);
  }
  EXPECT_EQ(readText(file), "x");
  writeSessionFile(file, s, true);
  EXPECT_EQ(readSessionFile(file).session.layout, "grid");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.root), fs::directory_iterator()), 1)
      << "no temporary file is left";
}

TEST(Session, TurnedAndSlabViewsRoundTripAndAbsentMeansAcquisitionPlanesThin) {
  Session s;
  const double a = 1.0 / 3.0;  // radians about the S axis, then a tilt about L
  const glm::dmat3 aboutS(glm::dvec3(std::cos(a), std::sin(a), 0),
                          glm::dvec3(-std::sin(a), std::cos(a), 0), glm::dvec3(0, 0, 1));
  const glm::dmat3 aboutL(glm::dvec3(1, 0, 0), glm::dvec3(0, std::cos(0.2), std::sin(0.2)),
                          glm::dvec3(0, -std::sin(0.2), std::cos(0.2)));
  s.views[0].rotation = aboutS;
  s.views[1].slab = {12.5, SlabMode::MinIp};
  s.views[2] = {aboutL * aboutS, {20.0 / 3.0, SlabMode::Mean}};
  s.centre = glm::dvec3(12.25, 34.0 / 3.0, 56.125);
  const Json j = jsonOf(s, "s.json");
  const Session r = sessionFromJson(j.dump(), "s.json").session;
  for (size_t o = 0; o < 3; ++o) {
    EXPECT_EQ(r.views[o].rotation, s.views[o].rotation) << o;  // exactly: the same planes
    EXPECT_EQ(r.views[o].slab.thicknessMm, s.views[o].slab.thicknessMm) << o;
    EXPECT_EQ(r.views[o].slab.mode, s.views[o].slab.mode) << o;
  }
  ASSERT_TRUE(r.centre.has_value());
  EXPECT_EQ(*r.centre, *s.centre);
  EXPECT_EQ(j["slices"]["views"]["coronal"]["slab-mode"], "minip");

  // Untouched views are not written, and a session without them (older files) reads as the
  // acquisition planes, thin, the crosshair on its voxel.
  const Json plain = jsonOf(Session{}, "s.json");
  EXPECT_FALSE(plain["slices"].contains("views"));
  EXPECT_FALSE(plain["slices"].contains("centre"));
  const Session p = sessionFromJson(plain.dump(), "s.json").session;
  EXPECT_FALSE(p.centre.has_value());
  for (const SessionView& v : p.views) {
    EXPECT_EQ(v.rotation, glm::dmat3(1.0));
    EXPECT_EQ(v.slab.thicknessMm, 0.0);
  }

  auto withView = [&](const Json& view) {
    Json bad = plain;
    bad["slices"]["views"]["axial"] = view;
    return readJsonError(bad);
  };
  EXPECT_NE(withView({{"rotation", {{1, 0, 0}, {0, 1, 0}, {0, 0.5, 1}}}})
                .find("field 'slices.views.axial.rotation' is not a rotation"),
            std::string::npos);
  EXPECT_NE(withView({{"rotation", {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}})  // a mirror
                .find("field 'slices.views.axial.rotation' is not a rotation"),
            std::string::npos);
  EXPECT_NE(withView({{"rotation", {{1, 0}, {0, 1}}}})
                .find("field 'slices.views.axial.rotation' must be 3 rows of 3 numbers"),
            std::string::npos);
  EXPECT_NE(withView({{"slab-mm", -2}}).find("field 'slices.views.axial.slab-mm' must be 0"),
            std::string::npos);
  EXPECT_NE(withView({{"slab-mode", "max"}}).find("field 'slices.views.axial.slab-mode' is wrong"),
            std::string::npos);
}

// Issue 35: sessions saved before the gradient opacity was rendered read with it off.
TEST(Session, AnOlderSessionReadsWithoutTheGradientOpacity) {
  Session s;
  s.render.mode = Mode::Dvr;
  Json j = jsonOf(s, "s.json");
  ASSERT_EQ(j["render"]["gradient-opacity"], "");
  j["render"].erase("gradient-opacity");
  const SessionRead read = sessionFromJson(j.dump(), "s.json");
  ASSERT_EQ(read.warnings.size(), 1u);
  EXPECT_EQ(read.warnings[0], "field 'render.gradient-opacity' missing: left at its default ()");
  EXPECT_TRUE(read.session.render.gradientOpacity.empty());
  EXPECT_EQ(read.session.render.mode, Mode::Dvr);
}

// Issue 35: sessions saved before per-segment transfer functions read with none (the volume's
// table everywhere), as they rendered; a saved one comes back exactly.
TEST(Session, AnOlderSessionReadsWithoutSegmentTfs) {
  Session s;
  s.render.mode = Mode::Dvr;
  s.render.segmentTfs[2] = findPreset("CT-Bone").tf.points;
  Json j = jsonOf(s, "s.json");
  EXPECT_EQ(sessionFromJson(j.dump(), "s.json").session.render.segmentTfs, s.render.segmentTfs);
  j["render"].erase("segment-tf");
  const SessionRead read = sessionFromJson(j.dump(), "s.json");
  ASSERT_EQ(read.warnings.size(), 1u);
  EXPECT_EQ(read.warnings[0], "field 'render.segment-tf' missing: left at its default ()");
  EXPECT_TRUE(read.session.render.segmentTfs.empty());
  EXPECT_EQ(read.session.render.mode, Mode::Dvr);
}

// Issue 41 item 7: "Handles in 3D view" and "Show planes in 3D view" were not in sessions.
TEST(Session, OverlaysRoundTripAndAnOlderSessionKeepsTheDefaults) {
  Session s;
  s.overlays = {false, false, true};
  const Json j = jsonOf(s, "s.json");
  EXPECT_EQ(j.at("overlays").dump(),
            R"({"clip-handles":false,"light-handle":false,"planes":true})");
  const SessionRead read = sessionFromJson(j.dump(), "s.json");
  EXPECT_TRUE(read.warnings.empty()) << read.warnings.front();
  EXPECT_EQ(read.session.overlays, (ViewOverlays{false, false, true}));

  // A session saved before: no object, or some keys only. Nothing to warn about.
  Json old = j;
  old.erase("overlays");
  const SessionRead before = sessionFromJson(old.dump(), "s.json");
  EXPECT_TRUE(before.warnings.empty()) << before.warnings.front();
  EXPECT_EQ(before.session.overlays, ViewOverlays{});
  old["overlays"] = {{"planes", true}};
  EXPECT_EQ(sessionFromJson(old.dump(), "s.json").session.overlays,
            (ViewOverlays{true, true, true}));

  old["overlays"] = {{"planes", "yes"}};
  EXPECT_EQ(readJsonError(old), "session s.json: field 'overlays.planes' must be true or false");
  old["overlays"] = true;
  EXPECT_EQ(readJsonError(old), "session s.json: field 'overlays' must be an object { ... }");
}

TEST(Session, TheModelsOverlaysAreSavedAndRestored) {
  AppModels saved;
  saved.render.setOverlays({false, true, true});
  const Session s = sessionFromModels(saved, {320, 240}, "grid");
  EXPECT_EQ(s.overlays, (ViewOverlays{false, true, true}));
  AppModels opened;
  int redraws = 0;
  opened.render.changed.connect([&](unsigned what) { redraws += (what & kSlices) != 0; });
  applySession(opened, sessionFromJson(sessionToJson(s, "s.json"), "s.json").session);
  EXPECT_EQ(opened.render.overlays(), (ViewOverlays{false, true, true}));
  EXPECT_GT(redraws, 0);  // the views and the panel hear of it
}

namespace voxray {

// Issue 35: the editor's lists and curve go into the session and come back into the editor,
// exactly; a table changed elsewhere since is saved as a table only.
TEST(Session, TheShapedTransferFunctionRoundTripsIntoTheEditor) {
  AppModels saved;
  saved.render.applyPreset("CT-Bone");
  TfEditorModel editor(saved.render);
  editor.setCurve(TfCurve::Smooth);
  editor.addOpacityPoint(777.25, 0.375);
  editor.setUnitDistance(1.0 / 3.0);
  const VolumeProperty shaped = editor.property();
  const Session s = sessionFromModels(saved, {320, 240}, "grid");
  ASSERT_TRUE(s.transferFunction.has_value());
  EXPECT_EQ(*s.transferFunction, shaped);
  const SessionRead read = sessionFromJson(sessionToJson(s, "s.json"), "s.json");
  EXPECT_TRUE(read.warnings.empty()) << read.warnings.front();
  ASSERT_TRUE(read.session.transferFunction.has_value());
  EXPECT_EQ(*read.session.transferFunction, shaped);

  AppModels opened;
  TfEditorModel reopened(opened.render);  // open before the session, as a user may
  applySession(opened, read.session);
  EXPECT_EQ(reopened.property(), shaped);
  EXPECT_EQ(opened.render.params().transferFunction, renderTable(shaped));

  // A preset chosen after shaping: the session keeps no stale lists.
  saved.render.applyPreset("CT-Skin");
  EXPECT_FALSE(sessionFromModels(saved, {320, 240}, "grid").transferFunction.has_value());
  // Older sessions have none; a bad one names the field.
  Json j = jsonOf(s, "s.json");
  j.erase("transfer-function");
  EXPECT_FALSE(sessionFromJson(j.dump(), "s.json").session.transferFunction.has_value());
  j = jsonOf(s, "s.json");
  j["transfer-function"]["opacity"][0][1] = 2.0;
  EXPECT_EQ(readJsonError(j),
            "session s.json: field 'transfer-function' is wrong: opacity point 1 has 2; it must "
            "lie in 0 ... 1");
}

}  // namespace voxray
