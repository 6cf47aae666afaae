// Issue 37: text and arrow annotations (annotation_model.h) placed in patient mm, shown on the
// slices within half a slice of their plane, taken back and redone one step at a time (alone
// and through Edit > Undo's order), and kept by the session file (older sessions without them
// still open).
#include <cmath>
#include <functional>
#include <memory>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "annotation_model.h"
#include "edit_order.h"
#include "session.h"
#include "session_state.h"
#include "slice_geometry.h"
#include "study_state.h"
#include "voxray/engine/measure.h"
#include "voxray/io/error.h"
#include "voxray/io/phantom.h"

using namespace voxray;
using ::testing::HasSubstr;

namespace {

// 0.7 x 0.8 x 2.5 mm voxels, axial acquisition (identity directions): a voxel's LPS position
// is origin + index * spacing, computed by hand below.
Volume axialVolume() {
  Volume v;
  v.dims = {64, 48, 20};
  v.spacingMm = {0.7, 0.8, 2.5};
  v.originMm = {-100.0, 50.0, 20.0};
  v.voxels.assign(v.voxelCount(), 0);
  return v;
}

// The same grid turned 30 degrees about z and 20 about x: a tilted, oblique acquisition.
Volume obliqueVolume() {
  Volume v = axialVolume();
  const double a = glm::radians(30.0), b = glm::radians(20.0);
  const glm::dmat3 rz(glm::dvec3(std::cos(a), std::sin(a), 0),
                      glm::dvec3(-std::sin(a), std::cos(a), 0), glm::dvec3(0, 0, 1));
  const glm::dmat3 rx(glm::dvec3(1, 0, 0), glm::dvec3(0, std::cos(b), std::sin(b)),
                      glm::dvec3(0, -std::sin(b), std::cos(b)));
  v.direction = rx * rz;
  return v;
}

std::shared_ptr<const Volume> phantom(int n) {
  return std::make_shared<const Volume>(makeHeadPhantom(n));
}

std::string inputErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Annotation, PlacedInPatientMillimetres) {
  const Volume v = axialVolume();
  const SliceAxes axial = sliceAxes(v.direction, Orientation::Axial);
  // Voxel (10, 20, 7): L = -100 + 10 * 0.7, P = 50 + 20 * 0.8, S = 20 + 7 * 2.5.
  const glm::dvec3 mm = voxelToPatient(v, {10, 20, 7});
  EXPECT_NEAR(mm.x, -93.0, 1e-12);
  EXPECT_NEAR(mm.y, 66.0, 1e-12);
  EXPECT_NEAR(mm.z, 37.5, 1e-12);
  AnnotationModel m;
  const int id = m.addText("lesion", mm, sliceNormal(v, axial));
  ASSERT_NE(m.find(id), nullptr);
  EXPECT_EQ(m.find(id)->anchorMm, glm::dvec3(-93.0, 66.0, 37.5));
  // The axial plane's normal is the i x j cross product: +S for this grid.
  EXPECT_NEAR(glm::distance(m.find(id)->normal, glm::dvec3(0, 0, 1)), 0.0, 1e-12);
  EXPECT_FALSE(m.find(id)->isArrow());
  EXPECT_EQ(m.selected(), id);
}

TEST(Annotation, ShownWithinHalfASliceOfItsPlaneOnly) {
  const Volume v = axialVolume();
  const SliceAxes axial = sliceAxes(v.direction, Orientation::Axial);
  const SliceAxes coronal = sliceAxes(v.direction, Orientation::Coronal);
  const glm::dvec3 n = sliceNormal(v, axial);
  AnnotationModel m;
  // 0.49 and 0.51 slices (1.225 and 1.275 mm at 2.5 mm) above slice 7: the edge of half a slice.
  const int inside = m.addText("in", voxelToPatient(v, {10, 20, 7.49}), n);
  const int beyond = m.addText("out", voxelToPatient(v, {10, 20, 7.51}), n);
  const int arrow =
      m.addArrow(voxelToPatient(v, {30, 30, 7.2}), voxelToPatient(v, {40, 5, 6.8}), n);
  // An arrow whose tail strays two slices off its head's plane belongs to neither.
  const int straddling =
      m.addArrow(voxelToPatient(v, {30, 30, 7}), voxelToPatient(v, {40, 5, 9}), n);
  auto on = [&](int id, const SliceAxes& a, int slice) {
    return annotationOnSlice(*m.find(id), v, a, slice);
  };
  EXPECT_TRUE(on(inside, axial, 7));
  EXPECT_FALSE(on(inside, axial, 8));
  EXPECT_FALSE(on(inside, axial, 6));
  EXPECT_FALSE(on(beyond, axial, 7));
  EXPECT_TRUE(on(beyond, axial, 8));
  EXPECT_TRUE(on(arrow, axial, 7));
  EXPECT_FALSE(on(arrow, axial, 8));
  for (int k = 0; k < v.dims.z; ++k) EXPECT_FALSE(on(straddling, axial, k)) << k;
  // Another plane through the point does not show it: it was made on an axial slice.
  EXPECT_FALSE(on(inside, coronal, 20));

  // On a tilted grid the slice plane's normal is not the slice axis; a point made on slice 12
  // still shows there only.
  const Volume t = obliqueVolume();
  const SliceAxes tAxial = sliceAxes(t.direction, Orientation::Axial);
  const glm::dvec3 tn = sliceNormal(t, tAxial);
  EXPECT_NEAR(glm::length(tn), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(tn, t.direction[0]), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(tn, t.direction[1]), 0.0, 1e-12);
  const Annotation a{0, "t", voxelToPatient(t, {50, 3, 12.3}), std::nullopt, tn};
  EXPECT_TRUE(annotationOnSlice(a, t, tAxial, 12));
  EXPECT_FALSE(annotationOnSlice(a, t, tAxial, 13));
  EXPECT_FALSE(annotationOnSlice(a, t, tAxial, 11));
}

TEST(Annotation, EachEditIsOneUndoStep) {
  AnnotationModel m;
  const glm::dvec3 n(0, 0, 1);
  EXPECT_FALSE(m.canUndo());
  const int text = m.addText("A", {1, 2, 3}, n);
  const int arrow = m.addArrow({4, 5, 6}, {7, 8, 9}, n);
  m.setText(text, "B");
  m.setText(text, "B");  // unchanged: no step
  m.remove(arrow);
  EXPECT_EQ(m.undoCount(), 4u);
  EXPECT_EQ(m.undoText(), "Undo Delete annotation");
  ASSERT_EQ(m.items().size(), 1u);

  m.undo();  // the arrow is back, with its points
  ASSERT_EQ(m.items().size(), 2u);
  ASSERT_NE(m.find(arrow), nullptr);
  EXPECT_EQ(*m.find(arrow)->tailMm, glm::dvec3(7, 8, 9));
  m.undo();
  EXPECT_EQ(m.find(text)->text, "A");
  EXPECT_EQ(m.undoText(), "Undo Add arrow");
  m.undo();
  m.undo();
  EXPECT_TRUE(m.items().empty());
  EXPECT_FALSE(m.canUndo());
  EXPECT_EQ(m.redoCount(), 4u);
  m.redo();
  m.redo();
  EXPECT_EQ(m.items().size(), 2u);
  EXPECT_EQ(m.redoText(), "Redo Edit annotation");
  // A new edit drops what was undone.
  m.addText("C", {0, 0, 0}, n);
  EXPECT_FALSE(m.canRedo());
  EXPECT_EQ(m.items().size(), 3u);
}

TEST(Annotation, EditUndoTakesBackAnnotationsInTheOrderMade) {
  static const Volume v = makeHeadPhantom(32);
  AppModels m;
  ViewHistory h(m);
  m.segmentation.reset(v);
  EditOrder order(h, m.segmentation, &m.annotations);
  const uint8_t l = m.segmentation.addSegment("Bone", {1, 1, 1});  // segments
  m.annotations.addArrow({1, 2, 3}, {4, 5, 6}, {0, 0, 1});         // annotations
  EXPECT_EQ(order.undoText(), "Undo Add arrow");
  order.undo();
  EXPECT_TRUE(m.annotations.items().empty());
  EXPECT_EQ(m.segmentation.segmentation().segments.size(), 1u);  // the segment stays
  EXPECT_EQ(order.redoText(), "Redo Add arrow");
  order.undo();
  EXPECT_TRUE(m.segmentation.segmentation().segments.empty());
  order.redo();
  order.redo();
  EXPECT_EQ(m.annotations.items().size(), 1u);
  (void)l;
}

TEST(Annotation, SessionKeepsThemAndOlderSessionsOpenWithout) {
  AppModels saved;
  openStudy(saved, phantom(32), "A");
  const Volume& v = *saved.document.volume();
  const glm::dvec3 n = sliceNormal(v, sliceAxes(v.direction, Orientation::Sagittal));
  saved.annotations.addText("Fracture, \"left\" ✓", {-12.125, 33.5, 7.0 / 3.0}, n);
  saved.annotations.addArrow({1.0 / 7.0, 2, 3}, {4, 5.5, 6}, n);
  const Session s = sessionFromModels(saved, {320, 240}, "grid");
  const std::string text = sessionToJson(s, "s.json");
  const SessionRead read = sessionFromJson(text, "s.json");
  EXPECT_TRUE(read.warnings.empty()) << read.warnings.front();
  AppModels opened;
  EXPECT_TRUE(openSession(opened, saved.document.volume(), "A", read.session).empty());
  ASSERT_EQ(opened.annotations.items().size(), 2u);
  for (size_t i = 0; i < 2; ++i) {  // exact: JSON keeps a double's 17 digits
    const Annotation &a = saved.annotations.items()[i], &b = opened.annotations.items()[i];
    EXPECT_EQ(b.text, a.text);
    EXPECT_EQ(b.anchorMm, a.anchorMm);
    EXPECT_EQ(b.tailMm, a.tailMm);
    EXPECT_EQ(b.normal, a.normal);
  }
  EXPECT_FALSE(opened.annotations.canUndo());  // a session is where reading starts

  // A session written before annotations existed: no key, no warning, none shown.
  auto j = nlohmann::json::parse(text);
  ASSERT_TRUE(j.contains("annotations"));
  j.erase("annotations");
  const SessionRead old = sessionFromJson(j.dump(), "old.json");
  EXPECT_TRUE(old.warnings.empty());
  AppModels reopened;
  reopened.annotations.addText("stale", {0, 0, 0}, {0, 0, 1});
  EXPECT_TRUE(openSession(reopened, saved.document.volume(), "A", old.session).empty());
  EXPECT_TRUE(reopened.annotations.items().empty());
  // And none annotated writes no key (what older readers would warn about).
  EXPECT_FALSE(nlohmann::json::parse(sessionToJson(old.session, "o.json")).contains("annotations"));
}

TEST(Annotation, BadEntriesAreNamedAndLeaveTheModel) {
  AnnotationModel m;
  m.addText("kept", {1, 2, 3}, {0, 0, 1});
  auto bad = [&](const char* json) {
    return inputErrorOf([&] { annotationsFromJson(nlohmann::json::parse(json), m); });
  };
  EXPECT_EQ(bad(R"({"text": "x"})"), "annotations in the session: expected a list [ ... ]");
  EXPECT_EQ(bad(R"([{"text": "x", "anchor_mm": [1, 2], "normal": [0, 0, 1]}])"),
            "annotation 1 in the session: 'anchor_mm' must be [x, y, z] in mm");
  EXPECT_EQ(bad(R"([{"text": "x", "anchor_mm": [1, 2, 3], "normal": [0, 0, 0]}])"),
            "annotation 1 in the session: 'normal' has no direction");
  EXPECT_EQ(bad(R"([{"text": "", "anchor_mm": [1, 2, 3], "normal": [0, 0, 1]}])"),
            "annotation 1 in the session: a text annotation has no text");
  EXPECT_EQ(bad(R"([{"anchor_mm": [1, 2, 3], "tail_mm": [1, 2, 1e9], "normal": [0, 0, 1]}])"),
            "annotation 1 in the session: 'tail_mm' is not a number within +-1e7 mm");
  ASSERT_EQ(m.items().size(), 1u);
  EXPECT_EQ(m.items()[0].text, "kept");
  // A session file whose annotations are not a list is refused naming the field.
  Session s;
  s.annotations = R"([{"text": "x", "anchor_mm": [1, 2, 3], "normal": [0, 0, 1]}])";
  auto j = nlohmann::json::parse(sessionToJson(s, "s.json"));
  j["annotations"] = 5;
  EXPECT_THAT(inputErrorOf([&] { sessionFromJson(j.dump(), "s.json"); }), HasSubstr("annotations"));
}
