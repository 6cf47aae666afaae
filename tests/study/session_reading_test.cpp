// Sessions keep the reading layout (issue 37: the grid's layout and which series a hanging
// protocol put in which view) and the fusion overlay's settings (issue 36): each value
// round-trips, older sessions open without them, and a missing overlay file is named while the
// rest of the session reads. And the results the SR takes: a distance picked in 3D is reported
// in 3D, a segment with its volume and SUVpeak.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include <nlohmann/json.hpp>

#include "../io/test_support.h"
#include "app_models.h"
#include "hanging_protocol.h"
#include "hanging_rule_json.h"
#include "layout_model.h"
#include "results_export.h"
#include "session.h"
#include "session_state.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"
#include "voxray/io/phantom_series.h"

namespace voxray {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

const std::vector<StudySeries> kReadingStudy = {
    {"1", "Scout", ""}, {"2", "AX T1", ""}, {"3", "AX T2 FLAIR", ""}, {"4", "COR T2", ""}};

using test::ruleFromJson;

TEST(ReadingLayout, ARulePlacesSeriesByDescriptionOrPlaceAndAMissingOneLeavesItsViewEmpty) {
  const HangingRule r = ruleFromJson(
      R"({"name": "MR brain", "layout": "2x2",
          "series": {"axial": "/t2\\s+flair/", "coronal": "cor", "3d": 2, "sagittal": "STIR"}})");
  ASSERT_EQ(r.series.size(), size_t(4));
  EXPECT_EQ(r.series.at(GridView::Volume3d).index, 2);
  const std::vector<PlacedView> placed = placeSeries(r, kReadingStudy);
  ASSERT_EQ(placed.size(), size_t(4));
  auto at = [&](GridView v) {
    return *std::find_if(placed.begin(), placed.end(),
                         [&](const PlacedView& p) { return p.view == v; });
  };
  EXPECT_EQ(at(GridView::Axial).series, "3");  // the regex, case ignored
  EXPECT_EQ(at(GridView::Axial).description, "AX T2 FLAIR");
  EXPECT_EQ(at(GridView::Coronal).series, "4");   // substring, case ignored
  EXPECT_EQ(at(GridView::Volume3d).series, "2");  // the second series by number
  EXPECT_EQ(at(GridView::Sagittal).series, "");
  EXPECT_EQ(at(GridView::Sagittal).note,
            "no series of this study matches 'STIR' (rule 'MR brain'); the view is left empty");
  // The grid shows the series of its first placed cell (2x2: axial first).
  EXPECT_EQ(shownSeries(ViewLayout::TwoByTwo, placed), std::optional<std::string>("3"));
  EXPECT_EQ(shownSeries(ViewLayout::MprPlus3d, placed), std::optional<std::string>("2"));
  ReadingLayout l{ViewLayout::TwoByTwo, keepShown(placed, "3")};
  // Coronal and 3D hold other series: emptied with a note; sagittal has none. Only axial stays.
  const auto cells = visibleCells(l);
  ASSERT_EQ(cells.size(), size_t(1));
  EXPECT_EQ(cells[0].view, GridView::Axial);
  EXPECT_EQ(cells[0].row, 0);
  EXPECT_EQ(cells[0].column, 0);
  const auto notes = emptyViewNotes(l);
  ASSERT_EQ(notes.size(), size_t(3));  // in the layout's cell order: coronal, sagittal, 3d
  EXPECT_EQ(notes[0].rfind("coronal: its series 'COR T2' is not the one shown", 0), 0u) << notes[0];
  EXPECT_EQ(notes[1].rfind("sagittal: no series of this study matches 'STIR'", 0), 0u);
  EXPECT_EQ(notes[2].rfind("3d: its series 'AX T1'", 0), 0u) << notes[2];
  // A place beyond the study's series is said with the count.
  const auto beyond =
      placeSeries(ruleFromJson(R"({"name": "x", "series": {"axial": 7}})"), kReadingStudy);
  EXPECT_EQ(beyond.at(0).note,
            "series 7 of the rule 'x' is not in this study (it has 4 volume series); the view is "
            "left empty");
  // Without placements every view of the layout shows the open volume.
  EXPECT_EQ(visibleCells(ReadingLayout{ViewLayout::OnePlusThree, {}}).size(), size_t(4));
}

TEST(ReadingLayout, RuleSeriesRoundTripAndBadOnesNameTheField) {
  const HangingRule r = ruleFromJson(R"({"name": "a", "series": {"axial": "T2", "3d": 3}})");
  const HangingRule back =
      parseHangingProtocols(hangingProtocolsJson(HangingProtocols{{r}})).rules.at(0);
  EXPECT_EQ(back.series, r.series);
  auto error = [](const std::string& rule) {
    try {
      ruleFromJson(rule);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error(R"({"name": "a", "series": {"oblique": "T2"}})"),
            "rules[0].series.oblique: not a view; give 3d, axial, coronal or sagittal");
  EXPECT_EQ(
      error(R"({"name": "a", "series": {"axial": 0}})").rfind("rules[0].series.axial: give", 0),
      0u);
  EXPECT_NE(
      error(R"({"name": "a", "series": {"axial": "/t2(/"}})").find("not a regular expression"),
      std::string::npos);
}

struct Scratch {
  fs::path root;
  Scratch() {
    std::random_device seed;
    root = fs::temp_directory_path() / ("voxray-session-reading-" + std::to_string(seed()));
    fs::create_directories(root);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
};

TEST(ReadingLayout, SessionRoundTripAndAnOlderSessionHasNone) {
  Scratch dir;
  Session s;
  s.reading =
      ReadingLayout{ViewLayout::TwoByTwo,
                    {{GridView::Axial, "3", "AX T2 FLAIR", ""},
                     {GridView::Sagittal, "", "", "no series of this study matches 'STIR'"}}};
  const std::string file = (dir.root / "s.json").string();
  writeSessionFile(file, s, false);
  const SessionRead r = readSessionFile(file);
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_TRUE(r.session.reading);
  EXPECT_EQ(*r.session.reading, *s.reading);
  EXPECT_EQ(layoutName(r.session.reading->layout), "2x2");
  // A session written before: no "reading".
  Json old = Json::parse(sessionToJson(Session{}, file));
  ASSERT_FALSE(old.contains("reading"));
  EXPECT_FALSE(sessionFromJson(old.dump(), file).session.reading);
  // A bad layout names the field.
  old["reading"] = {{"layout", "3x3"}};
  try {
    sessionFromJson(old.dump(), file);
    ADD_FAILURE() << "3x3 was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("field 'reading.layout' must be one of 1x1"),
              std::string::npos)
        << e.what();
  }
}

TEST(FusionSession, SettingsRoundTripWithValuesAndAnOlderSessionOpensWithNone) {
  Scratch dir;
  fs::create_directories(dir.root / "pet");
  Session s;
  Session::Fusion f;
  f.input = {(dir.root / "pet").string(), {{"series", "2"}}};
  f.colormap = "rainbow";
  f.lo = 1.25;
  f.hi = 7.0 / 3.0;  // not ten digits: kept exactly
  f.unit = "SUVbw";
  f.opacity = 0.35;
  f.on = false;
  s.fusion = f;
  const std::string file = (dir.root / "s.json").string();
  writeSessionFile(file, s, false);
  const Json j = Json::parse(sessionToJson(s, file));
  EXPECT_EQ(j["fusion"]["input"]["path"], "pet");  // beside the session: relative
  EXPECT_EQ(j["fusion"]["window"]["unit"], "SUVbw");
  const SessionRead r = readSessionFile(file);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_TRUE(r.missingFusion.empty());
  ASSERT_TRUE(r.session.fusion);
  EXPECT_EQ(*r.session.fusion, f);
  EXPECT_EQ(r.session.fusion->hi, 7.0 / 3.0);
  // Older sessions: no overlay.
  Json old = j;
  old.erase("fusion");
  EXPECT_FALSE(sessionFromJson(old.dump(), file).session.fusion);
  // Bad values name the field.
  auto error = [&](const char* key, Json value) {
    Json bad = j;
    bad["fusion"][key] = value;
    try {
      sessionFromJson(bad.dump(), file);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("opacity", 1.5).find("field 'fusion.opacity' must be 0 ... 1"),
            std::string::npos);
  EXPECT_NE(error("colormap", "jet").find("field 'fusion.colormap' must be one of hot-iron"),
            std::string::npos);
  EXPECT_NE(
      error("window", {{"lo", 5}, {"hi", 2}}).find("field 'fusion.window' must have lo below hi"),
      std::string::npos);
}

TEST(FusionSession, AMissingOverlayFileIsNamedAndTheRestOfTheSessionReads) {
  Scratch dir;
  fs::create_directories(dir.root / "pet");
  Session s;
  s.window = {350.0, 40.0};
  s.fusion = Session::Fusion{};
  s.fusion->input.path = (dir.root / "pet").string();
  const std::string file = (dir.root / "s.json").string();
  writeSessionFile(file, s, false);
  fs::remove_all(dir.root / "pet");
  const SessionRead r = readSessionFile(file);
  ASSERT_EQ(r.missingFusion.size(), size_t(1));  // relative and absolute are one place here
  EXPECT_EQ(r.missingFusion[0], (dir.root / "pet").string());
  EXPECT_TRUE(r.missingInput.empty());
  EXPECT_EQ(r.session.window.width, 350.0);  // the rest is read
  ASSERT_TRUE(r.session.fusion);
  EXPECT_EQ(movedDataMessage(file, r.missingFusion, "The session opens without the overlay."),
            "session " + file + ": its data is missing (not at " + (dir.root / "pet").string() +
                "); the data moved or was deleted. The session opens without the overlay.");
}

TEST(FusionSession, ThePetOverlaysSuvWindowIsSavedFromTheModelAndPutBack) {
  test::TempDir dir;
  writePetSpherePhantom(dir.file("pet"), PetSpherePhantom{});
  auto pet = std::make_shared<const Volume>(loadVolume(dir.file("pet")));
  ASSERT_TRUE(pet->suv);
  AppModels m;
  m.fusion.setOverlay(pet, "pet", nullptr);
  m.fusion.setSource(dir.file("pet"), {});
  FusionSettings set = m.fusion.settings();
  set.colormap = "grey";
  set.lo = 2.5;  // SUVbw
  set.hi = 6.75;
  set.opacity = 0.8;
  set.on = false;
  m.fusion.setSettings(set);
  const Session::Fusion saved = sessionFusion(m.fusion);
  EXPECT_EQ(saved.input.path, dir.file("pet"));
  EXPECT_EQ(saved.unit, "SUVbw");
  EXPECT_EQ(saved.lo, 2.5);
  EXPECT_EQ(saved.hi, 6.75);
  EXPECT_EQ(saved.colormap, "grey");
  EXPECT_EQ(saved.opacity, 0.8);
  EXPECT_FALSE(saved.on);
  // Another window: the overlay opened again starts from its first window (SUV 1 ... 6) and
  // takes the saved one back.
  AppModels again;
  again.fusion.setOverlay(pet, "pet", nullptr);
  EXPECT_EQ(again.fusion.settings().lo, 1.0);
  EXPECT_TRUE(applySessionFusion(again.fusion, saved).empty());
  EXPECT_EQ(again.fusion.settings(), set);
  EXPECT_EQ(again.fusion.sourcePath(), dir.file("pet"));
  // The 3D table takes the SUV window in Bq/mL: 2.5 SUV / factor.
  EXPECT_NEAR(fusionTable(*pet, again.fusion.settings()).points.front().hu, 2.5 / pet->suv->factor,
              1e-9 / pet->suv->factor);
  // A window saved in another unit is not taken as SUV: said, the first window stays.
  Session::Fusion bq = saved;
  bq.unit = "Bq/ml";
  AppModels third;
  third.fusion.setOverlay(pet, "pet", nullptr);
  const auto problems = applySessionFusion(third.fusion, bq);
  ASSERT_EQ(problems.size(), size_t(1));
  EXPECT_EQ(problems[0],
            "the overlay's window was saved in Bq/ml but the overlay now reads in SUVbw: its "
            "first window is shown instead");
  EXPECT_EQ(third.fusion.settings().lo, 1.0);
  EXPECT_EQ(third.fusion.settings().colormap, "grey");  // the rest is taken
  // sessionFromModels saves it with the study.
  const Session s =
      sessionFromModels(m, {100, 100}, "grid", ReadingLayout{ViewLayout::OneByTwo, {}});
  ASSERT_TRUE(s.fusion);
  EXPECT_EQ(*s.fusion, saved);
  ASSERT_TRUE(s.reading);
  EXPECT_EQ(s.reading->layout, ViewLayout::OneByTwo);
}

}  // namespace
}  // namespace voxray

namespace voxray {
namespace {

TEST(ResultsOut, ADistancePickedIn3dIsReportedIn3dAndSegmentsCarryTheirSuvPeak) {
  test::TempDir dir;
  const PetSpherePhantom phantom;
  writePetSpherePhantom(dir.file("pet"), phantom);
  const Volume pet = loadVolume(dir.file("pet"));
  MeasurementModel m;
  m.add(MeasureKind::Distance, {{10, 10, 16}, {20, 10, 16}}, 2);   // on slice 16
  m.add(MeasureKind::Distance, {{10, 10, 16}, {20, 10, 16}}, -1);  // picked in the 3D view
  const auto r = reportMeasurements(pet, m);
  ASSERT_EQ(r.size(), size_t(2));
  EXPECT_FALSE(r[0].in3d);
  EXPECT_EQ(measurementSlice(r[0]), 16);
  EXPECT_TRUE(r[1].in3d);
  EXPECT_EQ(measurementSlice(r[1]), -1);  // on no image: SCOORD3D in the SR
  EXPECT_DOUBLE_EQ(*r[1].value, 40.0);    // 10 voxels of 4 mm
  // The sphere as a segment: its group has the volume and the SUVpeak (the sphere's SUV).
  Segmentation s = emptySegmentation(pet);
  size_t inside = 0;
  for (size_t n = 0; n < s.labels.size(); ++n) {
    s.labels[n] = pet.toPhysical(pet.voxels[n]) > 10000.0 ? 1 : 0;
    inside += s.labels[n];
  }
  Segment sphere;
  sphere.name = "Sphere";
  s.segments = {sphere};
  const auto groups = reportSegments(s, pet);
  ASSERT_EQ(groups.size(), size_t(1));
  EXPECT_EQ(groups[0].kind, ReportKind::Segment);
  EXPECT_EQ(groups[0].label, "segment 1 Sphere");
  EXPECT_DOUBLE_EQ(*groups[0].volumeMm3, double(inside) * 64.0);
  const double suv = petSphereSuv(phantom);
  ASSERT_TRUE(groups[0].suvPeak);
  EXPECT_NEAR(*groups[0].suvPeak, suv, 1e-9 * suv);
  // Its mean is the volume's (Bq/mL): the report converts it to SUVbw as an ROI's.
  EXPECT_NEAR(pet.suv->toSuv(*groups[0].mean), suv, 1e-9 * suv);
}

// Issue 37: a segment's group knows its number in a DICOM SEG written from the same
// segmentation (its place in the list, not its label) and its centroid in voxels, which the
// SR gives as a SCOORD3D POINT.
TEST(ResultsOut, SegmentGroupsCarryTheirSegNumberAndCentroid) {
  Volume v;
  v.dims = {16, 12, 20};
  v.spacingMm = {0.5, 0.5, 2.0};
  v.voxels.assign(v.voxelCount(), 40);
  Segmentation s = emptySegmentation(v);
  auto box = [&](uint8_t label, glm::ivec3 lo, glm::ivec3 hi) {  // inclusive
    for (int k = lo.z; k <= hi.z; ++k)
      for (int j = lo.y; j <= hi.y; ++j)
        for (int i = lo.x; i <= hi.x; ++i) s.labels[v.index(i, j, k)] = label;
  };
  box(5, {1, 2, 3}, {4, 2, 5});      // centre (2.5, 2, 4): 4 x 1 x 3 voxels
  box(2, {10, 6, 12}, {11, 9, 19});  // centre (10.5, 7.5, 15.5): 2 x 4 x 8 voxels
  Segment first, second;
  first.label = 5, first.name = "First";
  second.label = 2, second.name = "Second";
  s.segments = {first, second};  // the SEG's segments 1 and 2, whatever their labels
  const auto groups = reportSegments(s, v);
  ASSERT_EQ(groups.size(), size_t(2));
  EXPECT_EQ(groups[0].label, "segment 5 First");
  EXPECT_EQ(groups[0].segmentNumber, 1);
  ASSERT_TRUE(groups[0].centroid);
  EXPECT_EQ(*groups[0].centroid, glm::dvec3(2.5, 2.0, 4.0));  // means of small integers: exact
  EXPECT_DOUBLE_EQ(*groups[0].volumeMm3, 12 * 0.5);
  EXPECT_EQ(groups[1].label, "segment 2 Second");
  EXPECT_EQ(groups[1].segmentNumber, 2);
  ASSERT_TRUE(groups[1].centroid);
  EXPECT_EQ(*groups[1].centroid, glm::dvec3(10.5, 7.5, 15.5));
  EXPECT_DOUBLE_EQ(*groups[1].volumeMm3, 64 * 0.5);
}

}  // namespace
}  // namespace voxray
