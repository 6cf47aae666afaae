// The 2D transfer-function editor's model (issue 35): the value x |gradient| histogram counts
// a volume whose gradient is known in the bins it must, and the primitives' edits are what the
// 3D view renders, undo step by undo step, with hit testing in histogram coordinates.
#include <gtest/gtest.h>

#include "render_state_model.h"
#include "tf2d_edit.h"
#include "tf2d_histogram.h"
#include "tf_editor_model.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/io/volume.h"

namespace voxray {
namespace {

// A ramp along j: stored 5 j, HU = 2 stored - 1000, j spacing 0.6 mm. Inside, the central
// difference is (5 * 2 stored) * 2 HU / (2 * 0.6 mm) = 16.67 HU/mm; on the two j faces the
// clamped neighbour halves it (8.33 HU/mm). Along i and k the values are constant (0 HU/mm),
// whatever their spacing.
constexpr double kRampG = 20.0 / 1.2;
Volume rampVolume() {
  Volume v;
  v.dims = {16, 20, 12};
  v.spacingMm = {0.7, 0.6, 1.5};
  v.slope = 2.0;
  v.intercept = -1000.0;
  v.voxels.resize(v.voxelCount());
  for (int z = 0; z < v.dims.z; ++z)
    for (int y = 0; y < v.dims.y; ++y)
      for (int x = 0; x < v.dims.x; ++x) v.voxels[v.index(x, y, z)] = int16_t(5 * y);
  return v;
}

uint64_t rowSum(const Tf2dHistogram& h, int row) {
  uint64_t s = 0;
  for (int c = 0; c < Tf2dHistogram::kValueBins; ++c) s += h.at(c, row);
  return s;
}

Tf2dPrimitive rect(double hu0, double hu1, double g0, double g1) {
  Tf2dPrimitive p;
  p.hu0 = hu0;
  p.hu1 = hu1;
  p.g0 = g0;
  p.g1 = g1;
  p.rgb = {1.0, 0.5, 0.25};
  p.opacity = 0.5;
  return p;
}

}  // namespace

TEST(Tf2dHistogram, ARampOfGHuPerMmLandsInTheGBin) {
  const Volume v = rampVolume();
  // 64 rows over 0 ... 64 HU/mm: one HU/mm a row, so 16.67 HU/mm is row 16, 8.33 row 8.
  Tf2dHistogram h = tf2dHistogram(v, 64.0);
  ASSERT_FALSE(h.empty());
  EXPECT_EQ(h.total, v.voxelCount());
  EXPECT_DOUBLE_EQ(h.huLo, -1000.0);
  EXPECT_DOUBLE_EQ(h.huHi, -1000.0 + 2.0 * 95.0);
  EXPECT_EQ(h.rowOf(kRampG), 16);
  EXPECT_EQ(rowSum(h, 16), uint64_t(16 * 18 * 12));  // every inner j
  EXPECT_EQ(rowSum(h, 8), uint64_t(16 * 2 * 12));    // the two j faces
  uint64_t all = 0;
  for (int r = 0; r < Tf2dHistogram::kGradientBins; ++r) all += rowSum(h, r);
  EXPECT_EQ(all, v.voxelCount());
  // The value axis: j = 10 (-900 HU, one slab of 16 x 12 voxels) in its own column (10 HU
  // between slabs, 190/256 HU a column), at the inner row.
  EXPECT_EQ(h.at(h.columnOf(-900.0), 16), uint64_t(16 * 12));
  EXPECT_EQ(h.at(h.columnOf(-1000.0), 8), uint64_t(16 * 12));  // j = 0, a face
  EXPECT_EQ(h.at(h.columnOf(-810.0), 8), uint64_t(16 * 12));   // j = 19, the other
  // Log counts: the fullest bin is 1, an empty one 0, a slab of 192 log(193)/log(193).
  std::vector<float> img = h.logImage();
  EXPECT_FLOAT_EQ(img[16 * 256 + size_t(h.columnOf(-900.0))], 1.0f);
  EXPECT_FLOAT_EQ(img[0], 0.0f);
}

TEST(Tf2dHistogram, TheAutomaticAxisTopIsThePercentileRoundedUp) {
  // The sample (every 4th j: 0, 4, ... 16) is 80% inner voxels: the 99th percentile is
  // 16.67 HU/mm (to a fine bin of about 0.1 HU/mm), rounded up to a multiple of 8: 24.
  Tf2dHistogram h = tf2dHistogram(rampVolume());
  EXPECT_DOUBLE_EQ(h.gradientMax, 24.0);
  EXPECT_EQ(rowSum(h, int(kRampG / 24.0 * 64.0)), uint64_t(16 * 18 * 12));  // row 44
}

TEST(Tf2dHistogram, ACancelledCountIsEmpty) {
  std::atomic<bool> cancel{true};
  EXPECT_TRUE(tf2dHistogram(rampVolume(), 64.0, &cancel).empty());
}

TEST(Tf2dEdit, HitTestingFindsHandlesThenBodiesTopFirst) {
  Tf2d tf;
  tf.primitives = {rect(0.0, 100.0, 10.0, 50.0), rect(50.0, 150.0, 20.0, 60.0)};
  Tf2dPrimitive tri = rect(300.0, 500.0, 0.0, 40.0);
  tri.shape = Tf2dShape::Triangle;
  tf.primitives.push_back(tri);
  // The overlap (75, 30) belongs to the one on top (index 1).
  EXPECT_EQ(tf2dHitTest(tf, 75.0, 30.0, 2.0, 1.0), (Tf2dHit{1, Tf2dPart::Body}));
  EXPECT_EQ(tf2dHitTest(tf, 25.0, 30.0, 2.0, 1.0), (Tf2dHit{0, Tf2dPart::Body}));
  // A corner within the tolerances is a handle, even over another body.
  EXPECT_EQ(tf2dHitTest(tf, 101.5, 49.5, 2.0, 1.0), (Tf2dHit{0, Tf2dPart::HighHuHighG}));
  EXPECT_EQ(tf2dHitTest(tf, 49.0, 20.5, 2.0, 1.0), (Tf2dHit{1, Tf2dPart::LowHuLowG}));
  EXPECT_FALSE(tf2dHitTest(tf, 200.0, 30.0, 2.0, 1.0));
  // The triangle: apex at 400 HU, |gradient| 0; at 20 HU/mm it spans 350 ... 450.
  EXPECT_EQ(tf2dHitTest(tf, 440.0, 20.0, 2.0, 1.0), (Tf2dHit{2, Tf2dPart::Body}));
  EXPECT_FALSE(tf2dHitTest(tf, 330.0, 20.0, 2.0, 1.0));  // in its box, outside its sides
}

TEST(Tf2dEdit, MovesAndResizesKeepTheShapeValid) {
  Tf2dPrimitive p = rect(0.0, 100.0, 10.0, 50.0);
  EXPECT_EQ(tf2dMoved(p, 25.0, 5.0), rect(25.0, 125.0, 15.0, 55.0));
  EXPECT_EQ(tf2dMoved(p, 0.0, -30.0), rect(0.0, 100.0, 0.0, 40.0));  // stops at |gradient| 0
  EXPECT_EQ(tf2dResized(p, Tf2dPart::HighHuHighG, 200.0, 80.0), rect(0.0, 200.0, 10.0, 80.0));
  EXPECT_EQ(tf2dResized(p, Tf2dPart::LowHuLowG, -40.0, -3.0), rect(-40.0, 100.0, 0.0, 50.0));
  // Dragged past the opposite corner: it keeps the minimum extents.
  EXPECT_EQ(tf2dResized(p, Tf2dPart::LowHuHighG, 500.0, 0.0),
            rect(100.0 - kTf2dMinHu, 100.0, 10.0, 10.0 + kTf2dMinG));
}

TEST(TfEditorModel, Tf2dEditsAreWhatTheViewRendersAndUndoSteps) {
  RenderStateModel r;
  r.applyPreset("CT-Bone");
  TfEditorModel m(r);
  ASSERT_TRUE(r.params().tf2d.empty());
  size_t i = m.addTf2dPrimitive(rect(200.0, 400.0, 30.0, 90.0), 120.0);
  EXPECT_EQ(i, 0u);
  EXPECT_EQ(m.property().tf2d.gradientMax, 120.0);  // the editor's axis top
  EXPECT_EQ(r.params().tf2d, m.property().tf2d);
  EXPECT_EQ(r.params().mode, Mode::Dvr);
  m.moveTf2dPrimitive(0, 50.0, -10.0);
  EXPECT_EQ(r.params().tf2d.primitives[0], rect(250.0, 450.0, 20.0, 80.0));
  m.resizeTf2dPrimitive(0, Tf2dPart::HighHuHighG, 600.0, 100.0);
  EXPECT_EQ(r.params().tf2d.primitives[0], rect(250.0, 600.0, 20.0, 100.0));
  m.setTf2dColor(0, {0.0, 2.0, 0.5});
  m.setTf2dOpacity(0, 0.8);
  m.setTf2dSoft(0, 0.3);
  const Tf2dPrimitive& q = r.params().tf2d.primitives[0];
  EXPECT_EQ(q.rgb, glm::dvec3(0.0, 1.0, 0.5));
  EXPECT_EQ(q.opacity, 0.8);
  EXPECT_EQ(q.soft, 0.3);
  validate(m.property().tf2d, "editor");
  // A drag of many moves is one step.
  m.beginGesture();
  for (int k = 0; k < 5; ++k) m.moveTf2dPrimitive(0, 10.0, 0.0);
  m.endGesture();
  EXPECT_EQ(r.params().tf2d.primitives[0].hu0, 300.0);
  m.undo();
  EXPECT_EQ(r.params().tf2d.primitives[0].hu0, 250.0);
  m.undo();  // the soft edge
  EXPECT_EQ(r.params().tf2d.primitives[0].soft, 0.0);
  m.undo();
  m.undo();
  EXPECT_EQ(r.params().tf2d.primitives[0].rgb, glm::dvec3(1.0, 0.5, 0.25));
  m.undo();
  m.undo();
  EXPECT_EQ(r.params().tf2d.primitives[0], rect(200.0, 400.0, 30.0, 90.0));
  m.redo();
  EXPECT_EQ(r.params().tf2d.primitives[0], rect(250.0, 450.0, 20.0, 80.0));
  m.removeTf2dPrimitive(0);
  EXPECT_TRUE(r.params().tf2d.empty());
  EXPECT_EQ(m.property().tf2d.gradientMax, 0.0);
  m.undo();
  EXPECT_EQ(r.params().tf2d.primitives.size(), 1u);
  // The view still holds the editor's function: nothing took it back from the view.
  EXPECT_TRUE(m.canUndo());
  // A preset chosen elsewhere (the panel) is what the view shows: the 2D function, which
  // would replace its table, goes, and the editor starts from the preset.
  r.applyPreset("CT-Skin");
  EXPECT_TRUE(r.params().tf2d.empty());
  EXPECT_TRUE(m.property().tf2d.empty());
  EXPECT_EQ(renderTable(m.property()), findPreset("CT-Skin").tf.points);
}

}  // namespace voxray
