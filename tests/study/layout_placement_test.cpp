// Issue 37: different series side by side in one layout. The layout model holds which series
// is in which cell: a rule's two series are the grid's (left column) and the one beside it
// (compare's right column), a third's cell is left empty and says why; the user's "Show series
// in this view" places one; sessions keep the placement with the series' UIDs and the prior's
// series, and a session's placement is checked against the series the study still has.
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "hanging_protocol.h"
#include "hanging_rule_json.h"
#include "layout_model.h"
#include "session.h"
#include "voxray/io/error.h"

namespace voxray {
namespace {

using Json = nlohmann::ordered_json;

const std::vector<StudySeries> kPlacementStudy = {{"1", "Scout", "1.2.3.1"},
                                                  {"2", "AX T1", "1.2.3.2"},
                                                  {"3", "AX T2 FLAIR", "1.2.3.3"},
                                                  {"4", "COR T2", "1.2.3.4"}};

using test::ruleFromJson;

const PlacedView& at(const std::vector<PlacedView>& placed, GridView v) {
  return *std::find_if(placed.begin(), placed.end(),
                       [&](const PlacedView& p) { return p.view == v; });
}

TEST(LayoutPlacement, TwoSeriesOfARuleShowSideBySideAndAThirdLeavesItsCellEmpty) {
  // The classic T1 | T2 hanging: 1x2 puts the axial view first, the 3D view beside it.
  const HangingRule r =
      ruleFromJson(R"({"name": "T1|T2", "layout": "1x2", "series": {"axial": "T2", "3d": 2}})");
  const ReadingLayout l{ViewLayout::OneByTwo, placeSeries(r, kPlacementStudy)};
  EXPECT_EQ(at(l.placed, GridView::Axial).uid, "1.2.3.3");  // the UID comes with the series
  EXPECT_EQ(at(l.placed, GridView::Volume3d).uid, "1.2.3.2");
  const auto shown = shownSeries(l.layout, l.placed);
  ASSERT_EQ(shown, std::optional<std::string>("3"));  // the first cell's: the left column
  const auto beside = besideSeries(l.layout, l.placed, *shown);
  ASSERT_TRUE(beside);
  EXPECT_EQ(beside->series, "2");  // the right column
  EXPECT_EQ(beside->view, GridView::Volume3d);
  const ReadingLayout kept{l.layout, keepShown(l.placed, *shown, beside->series)};
  EXPECT_EQ(kept, l);  // both series keep their cells
  EXPECT_EQ(visibleCells(kept).size(), size_t(2));
  EXPECT_TRUE(emptyViewNotes(kept).empty());
  EXPECT_EQ(seriesInCells(kept), (std::vector<std::string>{"3", "2"}));
  // One series only: nothing beside.
  EXPECT_FALSE(besideSeries(l.layout, {at(l.placed, GridView::Axial)}, "3"));

  // Three series in 2x2: the cells' order (axial, coronal, sagittal, 3d) picks two; the third
  // series' cell is emptied with a note that says why.
  const HangingRule three = ruleFromJson(
      R"({"name": "three", "layout": "2x2",
          "series": {"axial": "T1", "coronal": "COR", "sagittal": "FLAIR"}})");
  const auto placed3 = placeSeries(three, kPlacementStudy);
  const auto beside3 = besideSeries(ViewLayout::TwoByTwo, placed3, "2");
  ASSERT_TRUE(beside3);
  EXPECT_EQ(beside3->series, "4");  // coronal comes before sagittal
  const ReadingLayout l3{ViewLayout::TwoByTwo, keepShown(placed3, "2", "4")};
  EXPECT_EQ(at(l3.placed, GridView::Axial).series, "2");
  EXPECT_EQ(at(l3.placed, GridView::Coronal).series, "4");
  EXPECT_EQ(at(l3.placed, GridView::Sagittal).series, "");
  const auto notes = emptyViewNotes(l3);
  ASSERT_EQ(notes.size(), size_t(1));
  EXPECT_EQ(notes[0],
            "sagittal: its series 'AX T2 FLAIR' is a third one (two series show at once, side "
            "by side); the view is left empty");
  EXPECT_EQ(visibleCells(l3).size(), size_t(3));  // the 3D view shows the open volume
}

TEST(LayoutPlacement, ShowSeriesInThisViewPlacesItAndAMissingSeriesLeavesItsCellEmpty) {
  ReadingLayout l{ViewLayout::OneByTwo, {}};
  l = placeInView(l, GridView::Axial, kPlacementStudy[1]);
  l = placeInView(l, GridView::Volume3d, kPlacementStudy[3]);
  ASSERT_EQ(l.placed.size(), size_t(2));
  EXPECT_EQ(at(l.placed, GridView::Volume3d),
            (PlacedView{GridView::Volume3d, "4", "COR T2", "", "1.2.3.4"}));
  // Placed again: the cell's series is replaced, not added.
  l = placeInView(l, GridView::Volume3d, kPlacementStudy[2]);
  ASSERT_EQ(l.placed.size(), size_t(2));
  EXPECT_EQ(seriesInCells(l), (std::vector<std::string>{"2", "3"}));
  // A rule naming a series the study lacks: its cell is empty, with a note; the rest hang.
  const HangingRule r =
      ruleFromJson(R"({"name": "mr", "layout": "1x2", "series": {"axial": "T1", "3d": "DWI"}})");
  const ReadingLayout missing{ViewLayout::OneByTwo, placeSeries(r, kPlacementStudy)};
  EXPECT_FALSE(besideSeries(missing.layout, missing.placed, "2"));
  const auto cells = visibleCells(missing);
  ASSERT_EQ(cells.size(), size_t(1));
  EXPECT_EQ(cells[0].view, GridView::Axial);
  EXPECT_EQ(emptyViewNotes(missing),
            (std::vector<std::string>{"3d: no series of this study matches 'DWI' (rule 'mr'); "
                                      "the view is left empty"}));
}

TEST(LayoutPlacement, SessionKeepsTheSeriesUidsAndThePriorsSeries) {
  Session s;
  s.input.path = "/data/study";
  s.reading = ReadingLayout{ViewLayout::OneByTwo,
                            {PlacedView{GridView::Axial, "3", "AX T2 FLAIR", "", "1.2.3.3"},
                             PlacedView{GridView::Volume3d, "2", "AX T1", "", "1.2.3.2"}}};
  s.comparison = Session::Comparison{"/data/study", std::nullopt, 0, "2"};
  const std::string file = "/tmp/placement-session.json";  // only named, not written
  const std::string text = sessionToJson(s, file);
  const Json j = Json::parse(text);
  EXPECT_EQ(j["reading"]["views"]["axial"]["uid"], "1.2.3.3");
  EXPECT_EQ(j["reading"]["views"]["3d"]["uid"], "1.2.3.2");
  EXPECT_EQ(j["comparison"]["series"], "2");
  const SessionRead r = sessionFromJson(text, file);
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_TRUE(r.session.reading);
  EXPECT_EQ(*r.session.reading, *s.reading);
  ASSERT_TRUE(r.session.comparison);
  EXPECT_EQ(r.session.comparison->priorSeries, "2");
  // An older session (no UIDs, a prior without a series) reads as it did.
  Json old = j;
  old["reading"]["views"]["axial"].erase("uid");
  old["reading"]["views"]["3d"].erase("uid");
  old["comparison"].erase("series");
  const SessionRead o = sessionFromJson(old.dump(), file);
  EXPECT_TRUE(o.warnings.empty());
  EXPECT_EQ(o.session.reading->placed.at(0).uid, "");
  EXPECT_EQ(o.session.comparison->priorSeries, "");
}

TEST(LayoutPlacement, ASessionsPlacementIsCheckedAgainstTheSeriesStillThere) {
  const ReadingLayout saved{ViewLayout::TwoByTwo,
                            {PlacedView{GridView::Axial, "3", "AX T2 FLAIR", "", "1.2.3.3"},
                             PlacedView{GridView::Coronal, "4", "COR T2", "", "1.2.3.4"}}};
  // Everything still there: unchanged.
  EXPECT_EQ(checkPlacement(saved, kPlacementStudy), saved);
  // COR T2 removed from the study: its view is left empty and says which series went.
  std::vector<StudySeries> less(kPlacementStudy.begin(), kPlacementStudy.end() - 1);
  const ReadingLayout checked = checkPlacement(saved, less);
  EXPECT_EQ(checked.placed.at(0), saved.placed.at(0));
  EXPECT_EQ(checked.placed.at(1).series, "");
  EXPECT_EQ(emptyViewNotes(checked),
            (std::vector<std::string>{
                "coronal: its series 'COR T2' is no longer in the study; the view is left empty"}));
  // By UID, not by place: series 3 renumbered (its selector now "5") is still found...
  std::vector<StudySeries> renumbered = kPlacementStudy;
  renumbered[2].selector = "5";
  EXPECT_EQ(checkPlacement(saved, renumbered).placed.at(0).series, "3");
  // ... while another series that took number 4 is not COR T2.
  renumbered[3].uid = "1.2.3.99";
  EXPECT_EQ(checkPlacement(saved, renumbered).placed.at(1).series, "");
  // An older session without UIDs is checked by the selector.
  ReadingLayout old = saved;
  for (PlacedView& p : old.placed) p.uid.clear();
  EXPECT_EQ(checkPlacement(old, less).placed.at(0).series, "3");
  EXPECT_EQ(checkPlacement(old, less).placed.at(1).series, "");
}

// Issue 36 leftover: the "Link 3D look" box and the prior's 3D camera are kept by sessions;
// older sessions open linked with no saved camera; a bad camera names its field.
TEST(CompareSession, LinkLookAndThePriorsCameraRoundTrip) {
  Session s;
  s.input.path = "/data/study";
  CameraParams cam;
  cam.azimuthDeg = -37.25;
  cam.elevationDeg = 12.5;
  cam.zoom = 1.75;
  cam.distanceMm = 640.0;
  cam.panMm = {3.5, -8.25};
  cam.projection = Projection::Orthographic;
  cam.fovDeg = 24.0;
  s.comparison = Session::Comparison{"/data/prior", std::nullopt, 0, "", false, cam};
  const std::string file = "/tmp/compare-session.json";  // only named, not written
  const std::string text = sessionToJson(s, file);
  const Json j = Json::parse(text);
  EXPECT_EQ(j["comparison"]["link-look"], false);
  EXPECT_EQ(j["comparison"]["prior-camera"]["projection"], "orthographic");
  const SessionRead r = sessionFromJson(text, file);
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_TRUE(r.session.comparison && r.session.comparison->priorCamera);
  EXPECT_FALSE(r.session.comparison->linkLook);
  const CameraParams& back = *r.session.comparison->priorCamera;
  // Written as JSON numbers (shortest round trip): exact.
  EXPECT_EQ(back.azimuthDeg, cam.azimuthDeg);
  EXPECT_EQ(back.elevationDeg, cam.elevationDeg);
  EXPECT_EQ(back.zoom, cam.zoom);
  EXPECT_EQ(back.distanceMm, cam.distanceMm);
  EXPECT_EQ(back.panMm, cam.panMm);
  EXPECT_EQ(back.projection, Projection::Orthographic);
  EXPECT_EQ(back.fovDeg, cam.fovDeg);
  // An older session: linked, no camera.
  Json old = j;
  old["comparison"].erase("link-look");
  old["comparison"].erase("prior-camera");
  const SessionRead o = sessionFromJson(old.dump(), file);
  EXPECT_TRUE(o.warnings.empty());
  EXPECT_TRUE(o.session.comparison->linkLook);
  EXPECT_FALSE(o.session.comparison->priorCamera);
  // Linked and no camera: neither is written (the file stays as older builds wrote it).
  Session plain = s;
  plain.comparison = Session::Comparison{"/data/prior", std::nullopt};
  const Json p = Json::parse(sessionToJson(plain, file));
  EXPECT_FALSE(p["comparison"].contains("link-look"));
  EXPECT_FALSE(p["comparison"].contains("prior-camera"));
  // A bad zoom names the field.
  Json bad = j;
  bad["comparison"]["prior-camera"]["zoom"] = 0;
  try {
    sessionFromJson(bad.dump(), file);
    ADD_FAILURE() << "zoom 0 was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("comparison.prior-camera.zoom"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace voxray
