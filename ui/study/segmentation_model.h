#pragma once
// The segment editor's state, Qt-free: the segmentation on the open volume's grid, its list of
// segments, and every edit (labels or the list) as one undo step. The operations are
// voxray/io's (segment_edit.h, segment_recipe.h), the same the CLI runs.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "no_qt.h"
#include "notifier.h"
#include "voxray/io/segment_edit.h"
#include "voxray/io/segment_recipe.h"

namespace voxray {

// The labels of the box [lo, hi) as they are now (what the 3D view's copy takes after an edit).
LabelPatch copyLabels(const Segmentation& s, glm::ivec3 lo, glm::ivec3 hi);

class SegmentationModel {
 public:
  // An empty segmentation on the volume's grid, with no undo history.
  void reset(const Volume& v);
  // S (from a session) on volume V; throws an input Error when S is not on V's grid or is
  // inconsistent (segmentation_check.h), and keeps what it had then.
  void load(Segmentation s, const Volume& v);
  void clear();  // no volume: nothing to segment
  bool active() const { return active_; }
  const Segmentation& segmentation() const { return *s_; }
  // The segmentation as it is now, shared and never changed (copy on write: the model's next
  // edit copies the labels first if a snapshot is still held), for work off the GUI thread
  // (the statistics, the 3D view's copy) without copying the label map on it.
  std::shared_ptr<const Segmentation> snapshot() const { return s_; }

  // The segment list. Each edit is one undo step; a label that names no segment throws an
  // input Error.
  uint8_t addSegment(const std::string& name, glm::vec3 colour);  // the lowest free label
  void removeSegment(uint8_t label);                              // and its voxels
  void rename(uint8_t label, const std::string& name);
  void setColour(uint8_t label, glm::vec3 colour);
  void setOpacity(uint8_t label, float opacity);  // clamped to 0..1
  void setVisible(uint8_t label, bool visible);
  // How the segment shows in the 3D view: in the volume, as a surface, or hidden.
  void setDisplay3d(uint8_t label, Segment::Display3d display);
  void setCodes(uint8_t label, const Segment::Code& category, const Segment::Code& type);

  // Label edits, each one undo step (none when nothing changed).
  void paintSphere(glm::dvec3 centre, double radiusMm, uint8_t label, EditPolicy p = {});
  void eraseSphere(glm::dvec3 centre, double radiusMm, uint8_t label);
  void paintDisc(int axis, glm::dvec3 centre, double radiusMm, uint8_t label, EditPolicy p = {});
  void eraseDisc(int axis, glm::dvec3 centre, double radiusMm, uint8_t label);
  void setMask(uint8_t label, const Mask& m, const std::string& what, EditPolicy p = {});
  // The recipe voxray-cli segment runs, into `label`.
  void applyRecipe(const Volume& v, const SegmentRecipe& r, uint8_t label, EditPolicy p = {});

  // A paint or erase drag: the edits between begin and end make one undo step.
  void beginStroke();
  void endStroke();

  // What changed in the label map since the last takeEdits(), for the 3D view's copy of it:
  // a voxel box [lo, hi), or the whole map (a new or loaded segmentation); nothing when only
  // the segment list changed.
  struct Edits {
    bool whole = false;
    bool any = false;  // a box
    glm::ivec3 lo{0}, hi{0};
  };
  Edits takeEdits() { return std::exchange(edits_, {}); }

  bool canUndo() const { return done_ > 0; }
  bool canRedo() const { return done_ < steps_.size(); }
  size_t undoCount() const { return done_; }  // the steps undo can take back
  size_t redoCount() const { return steps_.size() - done_; }
  std::string undoText() const;  // "Undo Paint" or empty
  std::string redoText() const;
  void undo();
  void redo();

  Notifier<> changed;  // labels or segments changed

 private:
  struct Step {
    std::string what;
    LabelPatch patch;               // the labels it changed (swapped on undo and redo)
    std::vector<Segment> segments;  // the list on the other side of the step
  };
  Segment& segment(uint8_t label);
  Segmentation& mut();  // s_ to edit, detached from any snapshot first
  void push(std::string what, LabelPatch patch, std::vector<Segment> before);
  void swap(Step& step);
  void touched(const LabelPatch& p);  // adds the patch's box to edits_
  void touchedAll();

  std::shared_ptr<Segmentation> s_ = std::make_shared<Segmentation>();
  bool active_ = false;
  std::vector<Step> steps_;
  size_t done_ = 0;  // steps_[0, done_) are done; the rest undone (redo)
  bool inStroke_ = false;
  bool strokeStep_ = false;  // steps_.back() is the stroke's step: the next edit joins it
  Edits edits_;
};

}  // namespace voxray
