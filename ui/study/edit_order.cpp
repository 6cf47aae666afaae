#include "edit_order.h"

#include <algorithm>

namespace voxray {

namespace {

// Moves the last N steps of S from FROM's back to TO's back (latest first, so the order holds).
// A step FROM no longer holds (a new edit cleared the redo side) still goes to TO: the history
// has it.
void moveLast(std::vector<EditOrder::Source>& from, std::vector<EditOrder::Source>& to,
              EditOrder::Source s, size_t n) {
  for (size_t k = 0; k < n; ++k) {
    auto it = std::find(from.rbegin(), from.rend(), s);
    if (it != from.rend()) from.erase(std::next(it).base());
    to.push_back(s);
  }
}

}  // namespace

EditOrder::EditOrder(ViewHistory& view, SegmentationModel& segments, AnnotationModel* annotations)
    : view_(view), segments_(segments), annotations_(annotations) {
  known_[0] = countsOf(Source::View);
  known_[1] = countsOf(Source::Segments);
  known_[2] = countsOf(Source::Annotations);
  // What any could undo before this listened: older than anything recorded here.
  undo_.assign(known_[0].undo, Source::View);
  undo_.insert(undo_.end(), known_[1].undo, Source::Segments);
  undo_.insert(undo_.end(), known_[2].undo, Source::Annotations);
  viewConnection_ = view_.changed.connect([this] { follow(Source::View); });
  segmentsConnection_ = segments_.changed.connect([this] { follow(Source::Segments); });
  if (annotations_)
    annotationsConnection_ = annotations_->changed.connect([this] { follow(Source::Annotations); });
}

void EditOrder::setPriorMoves(PriorMoveHistory* history, ComparisonModel* model) {
  if (priorMoves_) priorMoves_->changed.disconnect(priorConnection_);
  priorMoves_ = history;
  priorModel_ = model;
  if (!priorMoves_ || !priorModel_) {
    priorMoves_ = nullptr;
    follow(Source::PriorMoves);  // its steps leave the order
    return;
  }
  priorConnection_ = priorMoves_->changed.connect([this] { follow(Source::PriorMoves); });
  follow(Source::PriorMoves);
}

EditOrder::~EditOrder() {
  if (priorMoves_) priorMoves_->changed.disconnect(priorConnection_);
  view_.changed.disconnect(viewConnection_);
  segments_.changed.disconnect(segmentsConnection_);
  if (annotations_) annotations_->changed.disconnect(annotationsConnection_);
}

EditOrder::Counts EditOrder::countsOf(Source s) const {
  if (s == Source::View) return {view_.undoCount(), view_.redoCount()};
  if (s == Source::Annotations)
    return annotations_ ? Counts{annotations_->undoCount(), annotations_->redoCount()} : Counts{};
  if (s == Source::PriorMoves)
    return priorMoves_ ? Counts{priorMoves_->undoCount(), priorMoves_->redoCount()} : Counts{};
  return {segments_.undoCount(), segments_.redoCount()};
}

void EditOrder::follow(Source s) {
  Counts& was = known_[int(s)];
  const Counts now = countsOf(s);
  if (stepping_ || (now.undo == was.undo && now.redo == was.redo)) {
    was = now;  // our own step (already moved), or a gesture going on within one step
    return;
  }
  if (now.undo < was.undo && now.redo == was.redo + (was.undo - now.undo)) {
    moveLast(undo_, redo_, s, was.undo - now.undo);  // undone elsewhere
  } else if (now.undo > was.undo && now.redo + (now.undo - was.undo) == was.redo) {
    moveLast(redo_, undo_, s, now.undo - was.undo);  // redone elsewhere
  } else if (now.undo > was.undo && now.redo == 0) {
    // New edits: the last thing edited; what was undone before can no longer be redone in
    // this order.
    undo_.insert(undo_.end(), now.undo - was.undo, s);
    redo_.clear();
  } else {
    // A new history (a study opened, a segmentation loaded) or one that dropped its oldest
    // steps: its steps go where they are known to be, the oldest.
    undo_.erase(std::remove(undo_.begin(), undo_.end(), s), undo_.end());
    redo_.erase(std::remove(redo_.begin(), redo_.end(), s), redo_.end());
    undo_.insert(undo_.begin(), now.undo, s);
    redo_.insert(redo_.begin(), now.redo, s);
  }
  was = now;
  changed.notify();
}

bool EditOrder::step(Source s, bool undo) {
  const Counts c = countsOf(s);
  if ((undo ? c.undo : c.redo) == 0) return false;
  stepping_ = true;
  if (s == Source::View)
    undo ? view_.undo() : view_.redo();
  else if (s == Source::Annotations)
    undo ? annotations_->undo() : annotations_->redo();
  else if (s == Source::PriorMoves) {
    const PriorPlacement now = PriorPlacement::of(*priorModel_);
    if (auto p = undo ? priorMoves_->undo(now) : priorMoves_->redo(now)) p->applyTo(*priorModel_);
  } else
    undo ? segments_.undo() : segments_.redo();
  stepping_ = false;
  known_[int(s)] = countsOf(s);
  return true;
}

void EditOrder::undo() {
  // A step whose history cannot take it back (dropped as its oldest) is skipped.
  while (!undo_.empty()) {
    const Source s = undo_.back();
    undo_.pop_back();
    if (step(s, true)) {
      redo_.push_back(s);
      break;
    }
  }
  changed.notify();
}

void EditOrder::redo() {
  while (!redo_.empty()) {
    const Source s = redo_.back();
    redo_.pop_back();
    if (step(s, false)) {
      undo_.push_back(s);
      break;
    }
  }
  changed.notify();
}

void EditOrder::undo(Source s) {
  if (step(s, true)) moveLast(undo_, redo_, s, 1);
  changed.notify();
}

void EditOrder::redo(Source s) {
  if (step(s, false)) moveLast(redo_, undo_, s, 1);
  changed.notify();
}

bool EditOrder::canUndo() const { return !undo_.empty(); }
bool EditOrder::canRedo() const { return !redo_.empty(); }

std::string EditOrder::textOf(Source s, bool undo) const {
  if (s == Source::View) return undo ? "Undo view change" : "Redo view change";
  if (s == Source::Annotations) return undo ? annotations_->undoText() : annotations_->redoText();
  if (s == Source::PriorMoves) return undo ? "Undo move prior" : "Redo move prior";
  return undo ? segments_.undoText() : segments_.redoText();
}

std::string EditOrder::undoText() const {
  return undo_.empty() ? std::string() : textOf(undo_.back(), true);
}

std::string EditOrder::redoText() const {
  return redo_.empty() ? std::string() : textOf(redo_.back(), false);
}

}  // namespace voxray
