// The segment editor's model (issue 34): list edits and label edits as undo steps, and the
// segmentation's place in the session file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "label_map_text.h"
#include "segmentation_model.h"
#include "session.h"
#include "session_state.h"
#include "study_state.h"
#include "voxray/io/error.h"
#include "voxray/io/phantom.h"

namespace voxray {
namespace {

using ::testing::HasSubstr;

std::shared_ptr<const Volume> phantom(int n) {
  return std::make_shared<const Volume>(makeHeadPhantom(n));
}

template <class F>
std::string inputErrorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

TEST(SegmentationModel, EveryListAndLabelEditIsOneUndoStepAndUndoRestoresTheBytes) {
  const auto v = phantom(32);
  SegmentationModel m;
  m.reset(*v);
  int changes = 0;
  m.changed.connect([&] { ++changes; });
  const auto empty = m.segmentation().labels;
  const uint8_t bone = m.addSegment("Bone", {1, 1, 0.8f});
  const uint8_t brain = m.addSegment("Brain", {1, 0.5f, 0.5f});
  EXPECT_EQ(bone, 1);
  EXPECT_EQ(brain, 2);
  m.paintSphere({16, 16, 16}, 20.0, bone);
  m.paintDisc(2, {16, 16, 16}, 10.0, brain, EditPolicy{true});
  m.rename(bone, "Skull");
  m.setColour(brain, {0.2f, 0.3f, 2.0f});
  m.setOpacity(brain, 0.5f);
  m.setVisible(bone, false);
  m.setCodes(brain, {"123037004", "SCT", "Anatomical Structure"}, {"12738006", "SCT", "Brain"});
  m.eraseSphere({16, 16, 16}, 3.0, 0);
  const auto final = m.segmentation();
  EXPECT_EQ(changes, 10);
  EXPECT_EQ(final.segments[0].name, "Skull");
  EXPECT_EQ(final.segments[1].colour, glm::vec3(0.2f, 0.3f, 1.0f));  // clamped to 0..1
  EXPECT_EQ(m.undoText(), "Undo Erase");
  // Undo of the list edits leaves the labels; of the paints, the labels go back byte for byte.
  for (int i = 0; i < 10; ++i) m.undo();
  EXPECT_FALSE(m.canUndo());
  EXPECT_EQ(m.segmentation().labels, empty);
  EXPECT_TRUE(m.segmentation().segments.empty());
  EXPECT_EQ(m.redoText(), "Redo Add segment");
  for (int i = 0; i < 10; ++i) m.redo();
  EXPECT_EQ(m.segmentation().labels, final.labels);
  EXPECT_EQ(m.segmentation().segments[1].type.meaning, "Brain");
  EXPECT_FALSE(m.segmentation().segments[0].visible);
  // A new edit after an undo drops the redo.
  m.undo();
  m.setOpacity(bone, 0.25f);
  EXPECT_FALSE(m.canRedo());
}

TEST(SegmentationModel, RemovingASegmentTakesItsVoxelsAndUndoBringsBothBack) {
  const auto v = phantom(32);
  SegmentationModel m;
  m.reset(*v);
  const uint8_t a = m.addSegment("A", {1, 0, 0});
  m.paintSphere({10, 10, 10}, 5.0, a);
  const auto painted = m.segmentation().labels;
  m.removeSegment(a);
  EXPECT_EQ(std::count(m.segmentation().labels.begin(), m.segmentation().labels.end(), a), 0);
  EXPECT_TRUE(m.segmentation().segments.empty());
  m.undo();
  EXPECT_EQ(m.segmentation().labels, painted);
  EXPECT_EQ(m.segmentation().segments.size(), 1u);
  EXPECT_THAT(inputErrorOf([&] { m.rename(9, "X"); }),
              HasSubstr("There is no segment with label 9."));
}

TEST(SegmentationModel, TheRecipeInTheEditorIsTheCliRecipe) {
  const auto v = phantom(48);
  SegmentationModel m;
  m.reset(*v);
  const uint8_t skull = m.addSegment("Skull", {1, 1, 1});
  SegmentRecipe r;
  r.threshold = {300, 3000};
  r.keepLargest = true;
  r.marginMm = 1.0;
  m.applyRecipe(*v, r, skull);
  const Segmentation cli = segmentationFromRecipe(*v, r);
  EXPECT_EQ(m.segmentation().labels, cli.labels);
  EXPECT_EQ(m.undoText(), "Undo Threshold");
}

TEST(LabelMapText, RoundTripsAndRefusesDamagedText) {
  std::vector<uint8_t> labels(100000, 0);
  for (size_t i = 0; i < labels.size(); i += 7) labels[i] = uint8_t(i % 5);
  const std::string text = labelMapToText(labels);
  EXPECT_LT(text.size(), labels.size() / 2);  // compressed
  EXPECT_EQ(labelMapFromText(text, labels.size(), "t"), labels);
  EXPECT_THAT(inputErrorOf([&] { labelMapFromText(text, labels.size() - 1, "t"); }),
              HasSubstr("t does not hold 99999 labels (one per voxel of its grid)"));
  EXPECT_THAT(inputErrorOf([&] { labelMapFromText(text + "A", labels.size(), "t"); }),
              HasSubstr("t is not base64 text"));
  EXPECT_THAT(inputErrorOf([&] { labelMapFromText("AAAA", labels.size(), "t"); }),
              HasSubstr("does not hold"));
}

TEST(SegmentationSession, TheSegmentationRoundTripsThroughTheSessionFile) {
  AppModels saved;
  openStudy(saved, phantom(32), "A");
  EXPECT_FALSE(sessionFromModels(saved, {320, 240}, "grid").segmentation);  // none yet
  saved.segmentation.reset(*saved.document.volume());
  const uint8_t bone = saved.segmentation.addSegment("Bone, \"cortical\"", {1, 0.9f, 0.8f});
  saved.segmentation.paintSphere({12, 14, 16}, 6.0, bone);
  const Session s = sessionFromModels(saved, {320, 240}, "grid");
  ASSERT_TRUE(s.segmentation);
  const SessionRead read = sessionFromJson(sessionToJson(s, "s.json"), "s.json");
  EXPECT_TRUE(read.warnings.empty()) << read.warnings.front();
  ASSERT_TRUE(read.session.segmentation);
  EXPECT_EQ(read.session.segmentation->labels, saved.segmentation.segmentation().labels);
  EXPECT_EQ(read.session.segmentation->segments[0].name, "Bone, \"cortical\"");

  AppModels opened;
  const auto problems = openSession(opened, saved.document.volume(), "A", read.session);
  EXPECT_TRUE(problems.empty());
  EXPECT_EQ(opened.segmentation.segmentation().labels, saved.segmentation.segmentation().labels);
  EXPECT_EQ(opened.segmentation.segmentation().segments[0].colour, glm::vec3(1, 0.9f, 0.8f));
}

TEST(SegmentationSession, ALabelMapOfAnotherGridIsAProblemNotAWrongVolume) {
  AppModels saved;
  openStudy(saved, phantom(32), "A");
  saved.segmentation.reset(*saved.document.volume());
  saved.segmentation.addSegment("Bone", {1, 1, 1});
  const Session s = sessionFromModels(saved, {320, 240}, "grid");
  AppModels opened;
  const auto problems = openSession(opened, phantom(40), "B", s);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_THAT(problems[0], HasSubstr("The session's segmentation was left out: The label map's "
                                     "geometry (32x32x32 voxels"));
  EXPECT_THAT(problems[0], HasSubstr("does not match the volume's (40x40x40 voxels"));
  EXPECT_FALSE(opened.segmentation.active());
  EXPECT_EQ(opened.document.volume()->dims, glm::ivec3(40));  // the volume is as opened
}

TEST(SegmentationSession, ADamagedSegmentationNamesItsField) {
  AppModels saved;
  openStudy(saved, phantom(16), "A");
  saved.segmentation.reset(*saved.document.volume());
  saved.segmentation.addSegment("Bone", {1, 1, 1});
  auto j =
      nlohmann::json::parse(sessionToJson(sessionFromModels(saved, {64, 64}, "grid"), "s.json"));
  auto damaged = j;
  damaged["segmentation"]["segments"][0]["label"] = 0;
  auto error = [](const nlohmann::json& d) {
    return inputErrorOf([&] { sessionFromJson(d.dump(), "s.json"); });
  };
  EXPECT_EQ(error(damaged),
            "session s.json: field 'segmentation' is wrong: segments[0].label must "
            "be a whole number from 1 to 255");
  damaged = j;
  damaged["segmentation"]["dims"] = {16, 16, 15};
  EXPECT_THAT(error(damaged), HasSubstr("label-map.text does not hold 3840 labels"));
  damaged = j;
  damaged["segmentation"]["label-map"]["encoding"] = "raw";
  EXPECT_THAT(error(damaged), HasSubstr("label-map.encoding must be \\\"zlib+base64\\\""));
}

}  // namespace
}  // namespace voxray
