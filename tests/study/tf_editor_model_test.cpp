// The transfer-function editor's model (issue 35): point edits keep the lists sorted and in
// range, every edit is what the 3D view renders, and a drag is one undo step.
#include <gtest/gtest.h>

#include "render_state_model.h"
#include "tf_editor_model.h"
#include "voxray/engine/transfer_function.h"

namespace voxray {
namespace {

RenderStateModel boneView() {
  RenderStateModel r;
  r.applyPreset("CT-Bone");
  return r;
}

}  // namespace

TEST(TfEditorModel, StartsFromWhatTheViewShowsAndChangesNothing) {
  RenderStateModel r = boneView();
  const RenderParams before = r.params();
  TfEditorModel m(r);
  EXPECT_EQ(renderTable(m.property()), findPreset("CT-Bone").tf.points);
  EXPECT_EQ(r.params().preset, "CT-Bone");
  EXPECT_EQ(toText(r.params()), toText(before));
  EXPECT_FALSE(m.canUndo());
  // In iso the editor starts from the dvr's default table, not the surface colour.
  RenderStateModel iso;
  iso.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Iso; });
  TfEditorModel fromIso(iso);
  EXPECT_EQ(renderTable(fromIso.property()), findPreset("CT-Bone").tf.points);
}

TEST(TfEditorModel, EveryEditIsWhatTheViewRenders) {
  RenderStateModel r = boneView();
  TfEditorModel m(r);
  int heard = 0;
  r.changed.connect([&](unsigned what) { heard += (what & kAppearance) ? 1 : 0; });
  size_t i = m.addOpacityPoint(600.0, 0.4);
  EXPECT_EQ(m.property().opacity[i], (OpacityNode{600.0, 0.4}));
  EXPECT_EQ(r.params().mode, Mode::Dvr);
  EXPECT_TRUE(r.params().preset.empty());
  EXPECT_EQ(r.params().transferFunction, renderTable(m.property()));
  EXPECT_NEAR(TransferFunction{r.params().transferFunction}.evaluate(600.0).a, 0.4, 1e-12);
  m.setCurve(TfCurve::Smooth);
  EXPECT_EQ(r.params().transferFunction, renderTable(m.property()));
  m.setUnitDistance(2.0);
  EXPECT_EQ(r.params().opacityUnitMm, 2.0);
  EXPECT_EQ(heard, 3);
}

TEST(TfEditorModel, PointsStayBetweenTheirNeighboursAndInRange) {
  RenderStateModel r;
  TfEditorModel m(r);
  VolumeProperty vp;
  vp.color = {{0.0, {1, 0, 0}}, {1000.0, {1, 1, 1}}};
  vp.opacity = {{0.0, 0.0}, {500.0, 0.5}, {1000.0, 1.0}};
  m.setProperty(vp);
  m.moveOpacityPoint(1, 2000.0, 1.7);  // past its right neighbour, above 1
  EXPECT_EQ(m.property().opacity[1], (OpacityNode{1000.0, 1.0}));
  m.moveOpacityPoint(1, -50.0, -0.2);
  EXPECT_EQ(m.property().opacity[1], (OpacityNode{0.0, 0.0}));
  EXPECT_EQ(m.addOpacityPoint(250.0, 0.25), 2u);  // sorted in after the two at 0 HU
  m.moveColorPoint(0, 5000.0);
  EXPECT_EQ(m.property().color[0].hu, 1000.0);
  size_t c = m.addColorPoint(500.0);  // takes the colour the curve has there
  EXPECT_EQ(m.property().color[c].rgb, glm::dvec3(1.0, 0.0, 0.0));  // both points at 1000
  m.setPointColor(c, {0.2, 1.5, -1.0});
  EXPECT_EQ(m.property().color[c].rgb, glm::dvec3(0.2, 1.0, 0.0));
  // A list keeps one point at least.
  while (m.property().opacity.size() > 1) m.removeOpacityPoint(0);
  m.removeOpacityPoint(0);
  EXPECT_EQ(m.property().opacity.size(), 1u);
  validate(m.property(), "editor");  // what the editor makes is always a valid property
}

TEST(TfEditorModel, ADragIsOneUndoStepAndUndoRestoresTheView) {
  RenderStateModel r = boneView();
  TfEditorModel m(r);
  const auto start = m.property();
  const auto startTable = renderTable(start);
  size_t i = m.addOpacityPoint(700.0, 0.1);
  const auto afterAdd = m.property();
  m.beginGesture();
  for (int k = 1; k <= 10; ++k) m.moveOpacityPoint(i, 700.0 + 10.0 * k, 0.1 + 0.05 * k);
  m.endGesture();
  EXPECT_EQ(m.property().opacity[i], (OpacityNode{800.0, 0.6}));
  m.undo();  // the whole drag
  EXPECT_EQ(m.property(), afterAdd);
  EXPECT_EQ(r.params().transferFunction, renderTable(afterAdd));
  m.undo();  // the add
  EXPECT_EQ(m.property(), start);
  EXPECT_EQ(r.params().transferFunction, startTable);
  EXPECT_FALSE(m.canUndo());
  m.redo();
  m.redo();
  EXPECT_EQ(m.property().opacity[i], (OpacityNode{800.0, 0.6}));
  // An edit that changes nothing is no step.
  m.moveOpacityPoint(i, 800.0, 0.6);
  m.undo();
  EXPECT_EQ(m.property(), afterAdd);
}

}  // namespace voxray

namespace voxray {

TEST(TfEditorModel, APresetChosenElsewhereBecomesWhatIsEdited) {
  RenderStateModel r = boneView();
  TfEditorModel m(r);
  m.addOpacityPoint(700.0, 0.1);
  r.applyPreset("CT-Skin");  // the panel's preset box
  EXPECT_EQ(renderTable(m.property()), findPreset("CT-Skin").tf.points);
  EXPECT_FALSE(m.canUndo());  // a new start
  // Switching to iso leaves the edited table as it is.
  m.addOpacityPoint(700.0, 0.1);
  const VolumeProperty edited = m.property();
  r.update(kAppearance, [](RenderParams& p) { p.mode = Mode::Iso; });
  EXPECT_EQ(m.property(), edited);
}

// Retargeted on a segment (the Segments panel's TF… Edit): edits go to that segment's own table
// and leave the volume's as it was; a segment without a table starts from the volume's, and
// undoing back to there gives it none again; one with a table starts from it.
TEST(TfEditorModel, OnASegmentEditsOnlyThatSegmentsTable) {
  RenderStateModel r = boneView();
  const RenderParams before = r.params();
  TfEditorModel m(r);
  m.setTarget(3);
  EXPECT_EQ(m.target(), 3);
  EXPECT_EQ(renderTable(m.property()), findPreset("CT-Bone").tf.points);  // the volume's
  EXPECT_TRUE(r.params().segmentTfs.empty());                             // nothing made yet
  const size_t i = m.addOpacityPoint(-500.0, 0.3);
  ASSERT_EQ(r.params().segmentTfs.count(3), size_t(1));
  EXPECT_EQ(r.params().segmentTfs.at(3), renderTable(m.property()));
  EXPECT_NEAR(TransferFunction{r.params().segmentTfs.at(3)}.evaluate(-500.0).a, 0.3, 1e-12);
  // The volume's table is untouched: still the preset, no table of its own.
  EXPECT_EQ(r.params().preset, "CT-Bone");
  EXPECT_EQ(r.params().transferFunction, before.transferFunction);
  m.beginGesture();  // a drag: one step
  m.moveOpacityPoint(i, -450.0, 0.5);
  m.moveOpacityPoint(i, -400.0, 0.6);
  m.endGesture();
  EXPECT_NEAR(TransferFunction{r.params().segmentTfs.at(3)}.evaluate(-400.0).a, 0.6, 1e-12);
  m.undo();
  EXPECT_NEAR(TransferFunction{r.params().segmentTfs.at(3)}.evaluate(-500.0).a, 0.3, 1e-12);
  m.undo();  // back to where it began: the segment has no table again
  EXPECT_TRUE(r.params().segmentTfs.empty());
  m.redo();
  EXPECT_EQ(r.params().segmentTfs.count(3), size_t(1));
  // A segment with a table of its own starts from it (its points, linear).
  r.update(kAppearance, [](RenderParams& p) { p.segmentTfs[5] = findPreset("CT-Skin").tf.points; });
  m.setTarget(5);
  EXPECT_EQ(renderTable(m.property()), findPreset("CT-Skin").tf.points);
  EXPECT_FALSE(m.canUndo());
  // The panel choosing another table for it: the editor follows.
  r.update(kAppearance, [](RenderParams& p) { p.segmentTfs[5] = findPreset("CT-Bone").tf.points; });
  EXPECT_EQ(renderTable(m.property()), findPreset("CT-Bone").tf.points);
  // Back on the volume: edits reach the volume's table again.
  m.setTarget(0);
  m.addOpacityPoint(700.0, 0.2);
  EXPECT_EQ(r.params().transferFunction, renderTable(m.property()));
  EXPECT_EQ(r.params().segmentTfs.at(5), findPreset("CT-Bone").tf.points);
}

}  // namespace voxray
