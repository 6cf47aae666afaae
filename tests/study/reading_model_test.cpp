// Issue 37, reading: the layouts' cells, hanging-protocol rules (matching, JSON round trip,
// bad input named by field), the reading keymap (duplicates refused naming both actions) and
// the results' helpers (report labels and values, key-image marks, the source-folder guard).
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "hanging_protocol.h"
#include "layout_model.h"
#include "reading_keymap.h"
#include "results_export.h"
#include "study_attributes.h"
#include "voxray/io/error.h"
#include "voxray/io/phantom.h"

namespace voxray {
namespace {

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Layouts, EveryLayoutHasItsCellsAndNamesRoundTrip) {
  for (ViewLayout l : viewLayouts()) {
    EXPECT_EQ(parseLayout(layoutName(l)), l);
    EXPECT_FALSE(layoutCells(l).empty());
  }
  EXPECT_EQ(layoutCells(ViewLayout::One).size(), 1u);
  EXPECT_EQ(layoutCells(ViewLayout::One)[0].view, GridView::Axial);
  EXPECT_EQ(layoutCells(ViewLayout::ThreeDOnly)[0].view, GridView::Volume3d);
  EXPECT_EQ(layoutCells(ViewLayout::OneByTwo).size(), 2u);
  // The classic grid: 3D top left.
  const auto mpr = layoutCells(ViewLayout::MprPlus3d);
  ASSERT_EQ(mpr.size(), 4u);
  EXPECT_EQ(mpr[0].view, GridView::Volume3d);
  EXPECT_EQ(mpr[0].row, 0);
  EXPECT_EQ(mpr[0].column, 0);
  // 1+3: the large view spans the three small ones' rows.
  const auto big = layoutCells(ViewLayout::OnePlusThree);
  EXPECT_EQ(big[0].rowSpan, 3);
  EXPECT_EQ(parseLayout("MPR+3D"), ViewLayout::MprPlus3d);
  EXPECT_FALSE(parseLayout("3x3"));
}

TEST(HangingProtocols, SubstringAndRegexMatchIgnoringCase) {
  EXPECT_TRUE(patternMatches("", "anything"));
  EXPECT_TRUE(patternMatches("ct", "CT"));
  EXPECT_TRUE(patternMatches("head", "CT HEAD 5mm"));
  EXPECT_FALSE(patternMatches("chest", "CT HEAD 5mm"));
  EXPECT_TRUE(patternMatches("/^ct (head|brain)/", "CT Brain axial"));
  EXPECT_FALSE(patternMatches("/^head/", "CT head"));
}

TEST(HangingProtocols, FirstMatchingRuleWins) {
  const HangingProtocols p = defaultHangingProtocols();
  const HangingRule* head = matchRule(p, {"CT", "", "Routine HEAD w/o"});
  ASSERT_NE(head, nullptr);
  EXPECT_EQ(head->name, "CT head");
  EXPECT_EQ(head->window, "Brain");
  EXPECT_EQ(head->preset, "CT-Bone");
  EXPECT_EQ(head->layout, ViewLayout::MprPlus3d);
  const HangingRule* chest = matchRule(p, {"CT", "CHEST", "Thorax 1.25"});
  ASSERT_NE(chest, nullptr);
  EXPECT_EQ(chest->window, "Lung");
  EXPECT_EQ(chest->layout, ViewLayout::TwoByTwo);
  const HangingRule* mr = matchRule(p, {"MR", "", "t1_mprage"});
  ASSERT_NE(mr, nullptr);
  EXPECT_EQ(mr->name, "MR");
  EXPECT_EQ(matchRule(p, {"PT", "", "WB"}), nullptr);
  // Every given field must match: body part too.
  HangingProtocols mine;
  mine.rules.push_back({"knee", "MR", "knee", "", ViewLayout::One, "", ""});
  EXPECT_EQ(matchRule(mine, {"MR", "HEAD", "t1"}), nullptr);
  EXPECT_NE(matchRule(mine, {"MR", "KNEE", "t1"}), nullptr);
}

TEST(HangingProtocols, JsonRoundTrip) {
  HangingProtocols p;
  p.rules.push_back(
      {"a", "CT", "/ab(do|d)/", "liver", ViewLayout::OnePlusThree, "Liver", "CT-Muscle"});
  p.rules.push_back({"b", "", "", "", std::nullopt, "", ""});
  const HangingProtocols q = parseHangingProtocols(hangingProtocolsJson(p));
  ASSERT_EQ(q.rules.size(), 2u);
  EXPECT_EQ(q.rules[0].name, "a");
  EXPECT_EQ(q.rules[0].modality, "CT");
  EXPECT_EQ(q.rules[0].bodyPart, "/ab(do|d)/");
  EXPECT_EQ(q.rules[0].seriesDescription, "liver");
  EXPECT_EQ(q.rules[0].layout, ViewLayout::OnePlusThree);
  EXPECT_EQ(q.rules[0].window, "Liver");
  EXPECT_EQ(q.rules[0].preset, "CT-Muscle");
  EXPECT_FALSE(q.rules[1].layout);
  EXPECT_EQ(hangingProtocolsJson(q), hangingProtocolsJson(p));
}

TEST(HangingProtocols, BadInputNamesTheField) {
  auto msg = [](const std::string& rules) {
    return errorOf([&] {
      parseHangingProtocols(R"({"voxray-hanging-protocols": 1, "rules": [)" + rules + "]}");
    });
  };
  EXPECT_NE(msg(R"({"name": "x", "layout": "3x3"})")
                .find("rules[0].layout: '3x3' is not a layout; give one of 1x1, 1x2, 2x2, "
                      "1+3, mpr+3d, 3d"),
            std::string::npos);
  EXPECT_NE(msg(R"({"name": "x"}, {"name": "y", "window": "Lungs"})")
                .find("rules[1].window: 'Lungs' is not a window preset"),
            std::string::npos);
  EXPECT_NE(msg(R"({"name": "x", "preset": "CT-Nothing"})")
                .find("rules[0].preset: 'CT-Nothing' is not a 3D preset"),
            std::string::npos);
  EXPECT_NE(msg(R"({"name": "x", "match": {"series-description": "/(head/"}})")
                .find("rules[0].match.series-description: '/(head/' is not a regular expression"),
            std::string::npos);
  EXPECT_NE(msg(R"({"name": "x", "match": {"bodypart": "head"}})")
                .find("rules[0].match.bodypart: not a field"),
            std::string::npos);
  EXPECT_NE(msg(R"({"layout": "1x1"})").find("rules[0].name: give each rule a name"),
            std::string::npos);
  EXPECT_NE(errorOf([] {
              parseHangingProtocols(R"({"voxray-hanging-protocols": 2, "rules": []})");
            }).find("version 2 is not one this build reads"),
            std::string::npos);
  EXPECT_NE(errorOf([] { parseHangingProtocols("{rules"); }).find("not JSON"), std::string::npos);
}

TEST(HangingProtocols, MissingFileGivesTheDefaultsAndABadFileNamesItself) {
  const auto dir = std::filesystem::temp_directory_path() / "voxray-reading-hp";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "hanging-protocols.json").string();
  std::filesystem::remove(path);
  EXPECT_EQ(loadHangingProtocols(path).rules.size(), defaultHangingProtocols().rules.size());
  HangingProtocols one;
  one.rules.push_back({"only", "CT", "", "", ViewLayout::One, "Bone", ""});
  saveHangingProtocols(path, one);
  ASSERT_EQ(loadHangingProtocols(path).rules.size(), 1u);
  EXPECT_EQ(loadHangingProtocols(path).rules[0].window, "Bone");
  std::ofstream(path)
      << R"({"voxray-hanging-protocols": 1, "rules": [{"name": "x", "layout": 4}]})";
  EXPECT_EQ(errorOf([&] { loadHangingProtocols(path); }).rfind(path + ": rules[0].layout", 0), 0u);
}

TEST(Keymap, DefaultsHaveNoDuplicateAndNumberKeysAreWindows) {
  EXPECT_NO_THROW(checkKeymap(defaultReadingActions(), plainKeyNormaliser));
  ReadingKeymap k;
  EXPECT_EQ(k.key("window-1"), "1");
  EXPECT_EQ(k.key("window-6"), "6");
  EXPECT_EQ(numberKeyWindows()[0], "Brain");
  EXPECT_EQ(numberKeyWindows()[5], "Bone");
  EXPECT_EQ(k.key("next-series"), "N");
  EXPECT_EQ(k.key("previous-series"), "Shift+N");
  EXPECT_EQ(k.key("mark-key-image"), "K");
}

TEST(Keymap, DuplicateKeyIsRefusedNamingBothActions) {
  ReadingKeymap k;
  const std::string m = errorOf([&] { k.setKey("tool-probe", "n"); });
  EXPECT_NE(m.find("'Next series of the study' (next-series)"), std::string::npos) << m;
  EXPECT_NE(m.find("'Probe (pointer with the value readout)' (tool-probe)"), std::string::npos)
      << m;
  EXPECT_EQ(k.key("tool-probe"), "P");  // unchanged
  const std::string j =
      errorOf([&] { k.applyJson(R"({"voxray-keymap": 1, "keys": {"tool-distance": "K"}})"); });
  EXPECT_NE(j.find("(mark-key-image)"), std::string::npos) << j;
  EXPECT_NE(j.find("(tool-distance)"), std::string::npos) << j;
  EXPECT_EQ(k.key("tool-distance"), "D");
}

TEST(Keymap, PagesMoveBySlabOrByTen) {
  EXPECT_EQ(pageSlices(0.0, 1.0), 10);  // thin
  EXPECT_EQ(pageSlices(10.0, 2.5), 4);  // a 10 mm slab over 2.5 mm slices
  EXPECT_EQ(pageSlices(5.0, 1.0), 5);
  EXPECT_EQ(pageSlices(0.4, 1.0), 1);  // never 0: a page always moves
}

TEST(Keymap, JsonRoundTripAndBadFields) {
  ReadingKeymap k;
  k.applyJson(
      R"({"voxray-keymap": 1, "keys": {"tool-distance": "M", "mark-key-image": "Ctrl+K"}})");
  EXPECT_EQ(k.key("tool-distance"), "M");
  EXPECT_EQ(k.key("mark-key-image"), "Ctrl+K");
  ReadingKeymap back;
  back.applyJson(k.toJson());
  for (const auto& a : k.actions()) EXPECT_EQ(back.key(a.id), a.key) << a.id;
  EXPECT_NE(errorOf([&] {
              k.applyJson(R"({"voxray-keymap": 1, "keys": {"zoom": "Z"}})");
            }).find("keys.zoom: not a reading action"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              k.applyJson(R"({"voxray-keymap": 1, "keys": {"tool-angle": 3}})");
            }).find("keys.tool-angle: give the key as text"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { k.applyJson(R"({"keys": {}})"); }).find("voxray-keymap"),
            std::string::npos);
  // A key the normaliser cannot read is named.
  const auto none = [](const std::string& s) { return s == "bad" ? std::string() : s; };
  EXPECT_NE(errorOf([&] {
              k.setKey("tool-angle", "bad", none);
            }).find("keys.tool-angle: 'bad' is not a key"),
            std::string::npos);
}

#ifdef VOXRAY_HAS_DICOM
// Body Part Examined as the headers say it (dcmdump): BRAIN for the Philips volume, HEAD for
// the GE tilt series; another series' UID finds none.
TEST(HangingProtocols, BodyPartComesFromTheSeriesHeaders) {
  const std::string dicom = VOXRAY_DATA_DIR "/dicom/";
  EXPECT_EQ(seriesBodyPart(dicom + "ct-philips-phantom/S2010", ""), "BRAIN");
  EXPECT_EQ(seriesBodyPart(dicom + "ct-ge-tilt", ""), "HEAD");
  EXPECT_EQ(seriesBodyPart(dicom + "ct-ge-tilt", "1.2.3.4"), "");
  EXPECT_EQ(seriesBodyPart(dicom + "no-such-folder", ""), "");
  HangingProtocols p;
  p.rules.push_back({"head", "CT", "/^(head|brain)$/", "", ViewLayout::One, "", ""});
  EXPECT_NE(matchRule(p, {"CT", seriesBodyPart(dicom + "ct-ge-tilt", ""), ""}), nullptr);
}
#endif

TEST(Results, MeasurementsGetTheCliLabelsAndTheEngineValues) {
  Volume v = makeHeadPhantom(32);
  v.spacingMm = {0.5, 0.75, 2.0};
  MeasurementModel m;
  m.add(MeasureKind::Distance, {{0, 0, 3}, {6, 8, 3}}, 2);
  m.add(MeasureKind::Angle, {{10, 0, 3}, {0, 0, 3}, {0, 10, 3}}, 2);
  m.add(MeasureKind::Rect, {{4, 4, 3}, {8, 8, 3}}, 2);
  m.add(MeasureKind::Distance, {{0, 0, 0}, {0, 0, 4}}, 2);
  const auto r = reportMeasurements(v, m);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0].label, "line 1");
  EXPECT_EQ(r[0].kind, ReportKind::Length);
  // 6 x 0.5 mm and 8 x 0.75 mm: sqrt(3² + 6²) mm.
  EXPECT_NEAR(*r[0].value, std::sqrt(9.0 + 36.0), 1e-9);
  EXPECT_EQ(r[1].label, "angle 1");
  EXPECT_NEAR(*r[1].value, 90.0, 1e-9);
  EXPECT_EQ(r[2].label, "rect 1");
  EXPECT_NEAR(r[2].areaMm2, 4 * 0.5 * 4 * 0.75, 1e-9);  // 2 mm x 3 mm
  EXPECT_TRUE(r[2].mean.has_value());
  EXPECT_EQ(r[3].label, "line 2");
  EXPECT_NEAR(*r[3].value, 8.0, 1e-9);  // 4 slices of 2 mm
}

TEST(Results, KeyImagesToggleAndKeepTheirOrder) {
  KeyImageSet k;
  int notes = 0;
  k.changed.connect([&] { ++notes; });
  EXPECT_TRUE(k.toggle(12));
  EXPECT_TRUE(k.toggle(3));
  EXPECT_TRUE(k.toggle(40));
  EXPECT_FALSE(k.toggle(3));
  EXPECT_EQ(k.slices(), (std::vector<int>{12, 40}));
  EXPECT_EQ(notes, 4);
}

TEST(Results, NothingIsWrittenIntoTheSourceFolder) {
  EXPECT_TRUE(insideFolder("/data/study/sr.dcm", "/data/study"));
  EXPECT_TRUE(insideFolder("/data/study/../study/x/sr.dcm", "/data/study/"));
  EXPECT_TRUE(insideFolder("/data/study", "/data/study"));
  EXPECT_FALSE(insideFolder("/data/study2/sr.dcm", "/data/study"));
  EXPECT_FALSE(insideFolder("/tmp/sr.dcm", "/data/study"));
  EXPECT_FALSE(insideFolder("/tmp/sr.dcm", ""));
  const std::string folder = VOXRAY_DATA_DIR "/dicom/ct-ge-tilt";
  EXPECT_NE(errorOf([&] {
              refuseSourceFolder(folder + "/sr.dcm", folder);
            }).find("results never go into the data's folder"),
            std::string::npos);
  EXPECT_EQ(errorOf([&] { refuseSourceFolder("/tmp/sr.dcm", folder); }), "");
  // A file input: its folder is the source.
  EXPECT_NE(errorOf([&] { refuseSourceFolder("/data/x/y.csv", "/data/x/ct.nii"); }), "");
}

}  // namespace
}  // namespace voxray
