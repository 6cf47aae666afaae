// Issue 34: Edit → Undo and Redo take back view changes and segment edits in the order the
// user made them, and follow a segment step taken back by the Segments panel's own Undo.
#include <gtest/gtest.h>

#include "edit_order.h"
#include "label_count.h"
#include "voxray/io/phantom.h"

namespace voxray {
namespace {

using test::countLabel;

void turn(AppModels& m, double azimuth) {
  m.render.update(kCamera, [&](RenderParams& p) { p.camera.azimuthDeg = azimuth; });
}

TEST(EditOrder, UndoTakesBackViewAndSegmentEditsInTheOrderMade) {
  static const Volume v = makeHeadPhantom(64);  // 4 mm voxels
  AppModels m;
  ViewHistory h(m);
  m.segmentation.reset(v);
  EditOrder order(h, m.segmentation);
  EXPECT_FALSE(order.canUndo());

  turn(m, 30.0);                                                   // view
  const uint8_t l = m.segmentation.addSegment("Bone", {1, 1, 1});  // segments
  m.segmentation.paintDisc(2, {32, 32, 32}, 20.0, l);              // segments
  const size_t painted = countLabel(m.segmentation.segmentation(), l);
  ASSERT_GT(painted, 50u);  // a 20 mm disc on 4 mm voxels: about π·5² = 78 voxels
  turn(m, 60.0);            // view
  EXPECT_EQ(order.undoText(), "Undo view change");

  order.undo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 30.0);
  EXPECT_EQ(countLabel(m.segmentation.segmentation(), l), painted);
  EXPECT_EQ(order.undoText(), m.segmentation.undoText());
  order.undo();  // the paint: its voxels are back to background
  EXPECT_EQ(countLabel(m.segmentation.segmentation(), l), 0u);
  EXPECT_EQ(m.segmentation.segmentation().segments.size(), 1u);
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 30.0);
  order.undo();  // the segment
  EXPECT_TRUE(m.segmentation.segmentation().segments.empty());
  order.undo();  // the first turn
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 0.0);
  EXPECT_FALSE(order.canUndo());

  order.redo();
  order.redo();
  order.redo();
  EXPECT_EQ(countLabel(m.segmentation.segmentation(), l), painted);
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 30.0);
  order.redo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 60.0);
  EXPECT_FALSE(order.canRedo());

  // The Segments panel's Undo (the model's own) takes the paint back: the order's next undo
  // is then the view's turn, and its redo the paint.
  order.undo();  // 60 → 30
  m.segmentation.undo();
  EXPECT_EQ(countLabel(m.segmentation.segmentation(), l), 0u);
  EXPECT_EQ(order.redoText(), m.segmentation.redoText());
  order.redo();
  EXPECT_EQ(countLabel(m.segmentation.segmentation(), l), painted);
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 30.0);
  // A new edit drops what could be redone; the focused editor's undo reaches its own step.
  m.segmentation.paintDisc(2, {10, 10, 32}, 8.0, l);
  EXPECT_FALSE(order.canRedo());
  turn(m, 90.0);
  order.undo(EditOrder::Source::Segments);
  EXPECT_EQ(countLabel(m.segmentation.segmentation(), l), painted);
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 90.0);
  order.undo();  // the turn, not the segment step already undone
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 30.0);
  EXPECT_EQ(countLabel(m.segmentation.segmentation(), l), painted);

  // A new segmentation (loaded, reset) starts its history again: its steps leave the order.
  m.segmentation.reset(v);
  order.undo();
  order.undo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 0.0);
  EXPECT_FALSE(order.canUndo());
}

// Issue 36: compare's Move prior drags take their place in Edit → Undo's order with the view's
// edits; the compare view's own Undo move (the history's) is followed.
TEST(EditOrder, PriorMovesAreUndoneInTheOrderMade) {
  AppModels m;
  ViewHistory h(m);
  EditOrder order(h, m.segmentation);
  ComparisonModel compare;
  PriorMoveHistory moves;
  order.setPriorMoves(&moves, &compare);
  EXPECT_FALSE(order.canUndo());
  auto drag = [&](const glm::dvec3& byMm) {  // as CompareView's drag: one step, then the move
    moves.beginDrag(PriorPlacement::of(compare));
    glm::dmat4 t = compare.movingToFixed();
    t[3] += glm::dvec4(byMm, 0.0);
    compare.setMovingToFixed(t);
  };
  auto shift = [&] { return glm::dvec3(compare.movingToFixed()[3]); };

  turn(m, 30.0);           // view
  drag({5.0, 0.0, 0.0});   // prior: aligns it
  drag({0.0, -2.5, 0.0});  // prior
  turn(m, 60.0);           // view
  EXPECT_EQ(order.undoText(), "Undo view change");
  order.undo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 30.0);
  EXPECT_EQ(shift(), glm::dvec3(5.0, -2.5, 0.0));  // the prior stays where it was dragged
  EXPECT_EQ(order.undoText(), "Undo move prior");
  order.undo();
  EXPECT_EQ(shift(), glm::dvec3(5.0, 0.0, 0.0));
  order.undo();  // the first drag: not aligned again
  EXPECT_FALSE(compare.aligned());
  EXPECT_EQ(shift(), glm::dvec3(0.0));
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 30.0);
  order.undo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 0.0);
  EXPECT_FALSE(order.canUndo());
  order.redo();
  order.redo();
  EXPECT_TRUE(compare.aligned());
  EXPECT_EQ(shift(), glm::dvec3(5.0, 0.0, 0.0));
  EXPECT_EQ(order.redoText(), "Redo move prior");

  // The compare view's own Undo move: the order's next redo is that drag, its next undo the
  // turn before it.
  order.redo();  // 5, -2.5
  moves.undo(PriorPlacement::of(compare))->applyTo(compare);
  EXPECT_EQ(shift(), glm::dvec3(5.0, 0.0, 0.0));
  EXPECT_EQ(order.redoText(), "Redo move prior");
  order.redo();
  EXPECT_EQ(shift(), glm::dvec3(5.0, -2.5, 0.0));
  // A new prior clears its moves: they leave the order, the view's steps stay.
  moves.clear();
  EXPECT_EQ(order.undoText(), "Undo view change");
  order.undo();
  EXPECT_DOUBLE_EQ(m.render.params().camera.azimuthDeg, 0.0);
  EXPECT_FALSE(order.canUndo());
  order.setPriorMoves(nullptr, nullptr);  // MOVES goes first (declared after the order)
}

}  // namespace
}  // namespace voxray
