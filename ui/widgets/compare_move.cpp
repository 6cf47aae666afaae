// Compare's Move prior mode (prior_move.h does the maths) and the 3D views' drag frames: a
// drag in one column's 3D view turns the other's camera too, so both render drag frames.
#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPushButton>

#include "compare_view.h"
#include "render_scheduler.h"
#include "slice_geometry.h"
#include "slice_view.h"
#include "volume_view.h"

namespace voxray::ui {

namespace {
// Ctrl+Z and Ctrl+Shift+Z (the Edit menu's Undo and Redo): -1, 1, or 0 for another key.
int undoKey(const QKeyEvent& k) {
  const auto mods = k.modifiers() & (Qt::ControlModifier | Qt::ShiftModifier | Qt::AltModifier);
  if (k.key() != Qt::Key_Z) return 0;
  if (mods == Qt::ControlModifier) return -1;
  return mods == (Qt::ControlModifier | Qt::ShiftModifier) ? 1 : 0;
}
}  // namespace

bool CompareView::eventFilter(QObject* watched, QEvent* e) {
  // In Move prior mode Ctrl+Z and Ctrl+Shift+Z take back and redo the prior's drags: the keys
  // come here as key presses (keyPressEvent) instead of as the Edit menu's shortcuts.
  if (e->type() == QEvent::ShortcutOverride && moveMode_ &&
      undoKey(*static_cast<QKeyEvent*>(e)) != 0) {
    e->accept();
    return true;
  }
  if (watched == fixedView_ || watched == movingView_) {
    if (moveMode_ && moveDrag(*static_cast<SliceView*>(watched), e)) return true;
  } else if ((watched == fixed3d_ || watched == moving3d_) && comparison_.linked() && hasPrior()) {
    RenderScheduler& other = watched == fixed3d_ ? *priorScheduler_ : studyScheduler_;
    const auto type = e->type();
    if (type == QEvent::MouseButtonPress ||
        (type == QEvent::MouseMove && static_cast<QMouseEvent*>(e)->buttons() != Qt::NoButton))
      other.beginInteraction();
    else if (type == QEvent::MouseButtonRelease)
      other.endInteraction();
  }
  return QWidget::eventFilter(watched, e);
}

ScreenPlane CompareView::screenPlane(SliceView& view, ComparisonModel::Side side) const {
  const bool fixed = side == ComparisonModel::Side::Fixed;
  const VolumeGeometry& g = fixed ? comparison_.fixed() : comparison_.moving();
  const CrosshairModel& c = fixed ? study_.crosshair : prior_->crosshair;
  const SliceAxes& axes = view.axes();
  const double slice = c.centre()[axes.nAxis];
  auto mm = [&](QPointF w) {
    const glm::dvec2 s = view.toSlice(w);
    return g.patientOf(sliceToVoxel(axes, g.dims, s.x, s.y, slice));
  };
  ScreenPlane p;
  const glm::dvec3 origin = mm(QPointF(0.0, 0.0));
  p.rightMm = mm(QPointF(1.0, 0.0)) - origin;  // the view's pixel spacing along its axes
  p.downMm = mm(QPointF(0.0, 1.0)) - origin;
  const glm::dvec2 s = voxelToSlice(axes, g.dims, c.centre());
  const QPointF at = view.toWidget(s.x, s.y);
  p.pivotPx = {at.x(), at.y()};
  p.pivotMm = g.patientOf(c.centre());
  return p;
}

bool CompareView::moveDrag(SliceView& view, QEvent* e) {
  const auto type = e->type();
  if (type != QEvent::MouseButtonPress && type != QEvent::MouseMove &&
      type != QEvent::MouseButtonRelease)
    return false;
  const auto* m = static_cast<QMouseEvent*>(e);
  const glm::dvec2 at(m->position().x(), m->position().y());
  if (type == QEvent::MouseButtonPress) {
    if (m->button() != Qt::LeftButton || !hasPrior() || study_.document.empty()) return false;
    const auto side =
        &view == fixedView_ ? ComparisonModel::Side::Fixed : ComparisonModel::Side::Moving;
    moveDrag_ = MoveDrag{side,
                         bool(m->modifiers() & Qt::ShiftModifier),
                         at,
                         screenPlane(view, side),
                         PriorPlacement::of(comparison_),
                         false};
    return true;
  }
  if (!moveDrag_) return false;  // hovering: the view's readout
  MoveDrag& d = *moveDrag_;
  if (at != d.fromPx) {
    if (!d.moved) history_.beginDrag(d.before);  // one undo step per drag, none per click
    d.moved = true;
    const glm::dmat4& from = d.before.movingToFixed;
    comparison_.setMovingToFixed(d.turn ? turnedPrior(from, d.side, d.plane, d.fromPx, at)
                                        : movedPrior(from, d.side, d.plane, d.fromPx, at));
    priorScheduler_->beginInteraction();  // the prior's 3D camera follows: drag frames
  }
  if (type == QEvent::MouseButtonRelease) {
    if (d.moved) priorScheduler_->endInteraction();
    moveDrag_.reset();
    refreshMoveButtons();
  }
  return true;
}

bool CompareView::undoKeyPressed(QKeyEvent* e) {
  const int k = moveMode_ ? undoKey(*e) : 0;
  if (k < 0) undoMove();
  if (k > 0) redoMove();
  return k != 0;
}

void CompareView::setMovePrior(bool on) {
  moveMode_ = on;
  moveDrag_.reset();
  moveButton_->setChecked(on);
  message_ =
      on ? "Move prior: drag in a slice view to move the prior, Shift+drag to turn it" : QString();
  refreshStatus();
}

void CompareView::undoMove() {
  if (auto back = history_.undo(PriorPlacement::of(comparison_))) back->applyTo(comparison_);
  refreshMoveButtons();
}

void CompareView::redoMove() {
  if (auto next = history_.redo(PriorPlacement::of(comparison_))) next->applyTo(comparison_);
  refreshMoveButtons();
}

void CompareView::refreshMoveButtons() {
  undoButton_->setEnabled(history_.canUndo());
  redoButton_->setEnabled(history_.canRedo());
}

}  // namespace voxray::ui
