// A segment's 3D display (issue 34: in the volume, as a surface, hidden): one undo step, kept in
// the session file, and sessions from before it open as they showed (in the volume).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "segmentation_json.h"
#include "segmentation_model.h"
#include "session.h"
#include "session_state.h"
#include "study_state.h"
#include "voxray/io/error.h"
#include "voxray/io/phantom.h"

namespace voxray {
namespace {

using ::testing::HasSubstr;
using D = Segment::Display3d;

TEST(SegmentDisplay3d, EachChangeIsOneUndoStepAndTheSameChoiceNone) {
  SegmentationModel m;
  m.reset(makeHeadPhantom(16));
  const uint8_t bone = m.addSegment("Bone", {1, 1, 1});
  EXPECT_EQ(m.segmentation().find(bone)->display3d, D::Volume);  // as before the choice
  const size_t steps = m.undoCount();
  m.setDisplay3d(bone, D::Surface);
  EXPECT_EQ(m.undoCount(), steps + 1);
  EXPECT_EQ(m.undoText(), "Undo Segment 3D display");
  m.setDisplay3d(bone, D::Surface);  // nothing changes: no step
  EXPECT_EQ(m.undoCount(), steps + 1);
  m.setDisplay3d(bone, D::Hidden);
  m.undo();
  EXPECT_EQ(m.segmentation().find(bone)->display3d, D::Surface);
  m.undo();
  EXPECT_EQ(m.segmentation().find(bone)->display3d, D::Volume);
  m.redo();
  EXPECT_EQ(m.segmentation().find(bone)->display3d, D::Surface);
  EXPECT_THROW(m.setDisplay3d(99, D::Surface), Error);  // no such segment
}

TEST(SegmentDisplay3d, TheSessionKeepsItAndOldSessionsShowInTheVolume) {
  AppModels saved;
  openStudy(saved, std::make_shared<const Volume>(makeHeadPhantom(16)), "A");
  saved.segmentation.reset(*saved.document.volume());
  const uint8_t a = saved.segmentation.addSegment("Skull", {1, 1, 1});
  const uint8_t b = saved.segmentation.addSegment("Brain", {1, 0, 0});
  const uint8_t c = saved.segmentation.addSegment("Table", {0, 0, 1});
  saved.segmentation.setDisplay3d(a, D::Surface);
  saved.segmentation.setDisplay3d(c, D::Hidden);
  auto j =
      nlohmann::json::parse(sessionToJson(sessionFromModels(saved, {64, 64}, "grid"), "s.json"));
  const auto& segs = j["segmentation"]["segments"];
  EXPECT_EQ(segs[0]["display-3d"], "surface");
  EXPECT_EQ(segs[1]["display-3d"], "volume");
  EXPECT_EQ(segs[2]["display-3d"], "hidden");
  const SessionRead read = sessionFromJson(j.dump(), "s.json");
  AppModels opened;
  EXPECT_TRUE(openSession(opened, saved.document.volume(), "A", read.session).empty());
  const Segmentation& s = opened.segmentation.segmentation();
  EXPECT_EQ(s.find(a)->display3d, D::Surface);
  EXPECT_EQ(s.find(b)->display3d, D::Volume);
  EXPECT_EQ(s.find(c)->display3d, D::Hidden);

  // A session written before the choice existed: no key, every segment in the volume.
  auto old = j;
  for (auto& seg : old["segmentation"]["segments"]) seg.erase("display-3d");
  const SessionRead oldRead = sessionFromJson(old.dump(), "s.json");
  ASSERT_TRUE(oldRead.session.segmentation);
  for (const Segment& seg : oldRead.session.segmentation->segments)
    EXPECT_EQ(seg.display3d, D::Volume);

  auto damaged = j;
  damaged["segmentation"]["segments"][1]["display-3d"] = "glass";
  try {
    sessionFromJson(damaged.dump(), "s.json");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("segments[1].display-3d must be volume, surface or hidden"));
  }
}

}  // namespace
}  // namespace voxray
