#pragma once
// Edit → Undo and Redo over the view's history, the segment editor's, the annotations' (when
// given) and compare's prior moves (once set), in the order the user
// made the edits: Ctrl+Z takes back the last edit of either, the next Ctrl+Z the one before.
// Each history keeps its own steps (ViewHistory, SegmentationModel); this keeps only which of
// the two each step was. It follows their step counts, so a step taken back elsewhere (the
// Segments panel's own Undo) leaves the order right.
#include <cstddef>
#include <string>
#include <vector>

#include "annotation_model.h"
#include "no_qt.h"
#include "prior_move.h"
#include "segmentation_model.h"
#include "view_history.h"

namespace voxray {

class EditOrder {
 public:
  enum class Source { View, Segments, Annotations, PriorMoves };
  // Listens to each until destroyed (destroy it before them).
  EditOrder(ViewHistory& view, SegmentationModel& segments, AnnotationModel* annotations = nullptr);
  ~EditOrder();
  EditOrder(const EditOrder&) = delete;
  EditOrder& operator=(const EditOrder&) = delete;

  // Compare's Move prior drags (issue 36): HISTORY's steps put back onto MODEL, in this order
  // too. Listens until destroyed or set again (nullptr: none): HISTORY must outlive this
  // order or be set away first (the window's order goes before its compare view).
  void setPriorMoves(PriorMoveHistory* history, ComparisonModel* model);

  bool canUndo() const;
  bool canRedo() const;
  // What the next undo or redo does, for the menu's tooltip: "Undo Paint", "Undo view change";
  // empty when there is none.
  std::string undoText() const;
  std::string redoText() const;
  void undo();
  void redo();
  // Undo or redo in one history only (the focused segment editor's Ctrl+Z); the order follows.
  void undo(Source s);
  void redo(Source s);

  Notifier<> changed;  // canUndo, canRedo or the texts may have changed

 private:
  struct Counts {
    size_t undo = 0, redo = 0;
  };
  Counts countsOf(Source s) const;
  void follow(Source s);
  bool step(Source s, bool undo);
  std::string textOf(Source s, bool undo) const;

  ViewHistory& view_;
  SegmentationModel& segments_;
  AnnotationModel* annotations_;
  PriorMoveHistory* priorMoves_ = nullptr;
  ComparisonModel* priorModel_ = nullptr;
  std::vector<Source> undo_, redo_;  // oldest first; the back is the next step
  Counts known_[4];
  bool stepping_ = false;
  int viewConnection_ = 0, segmentsConnection_ = 0, annotationsConnection_ = 0,
      priorConnection_ = 0;
};

}  // namespace voxray
