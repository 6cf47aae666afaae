#pragma once
// The segment editor's state, Qt-free: the segmentation on the open volume's grid, its list of
// segments, and every edit (labels or the list) as one undo step. The operations are
// voxray/io's (segment_edit.h, segment_recipe.h), the same the CLI runs.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "no_qt.h"
#include "notifier.h"
#include "voxray/io/segment_edit.h"
#include "voxray/io/segment_recipe.h"

namespace voxray {

class SegmentationModel {
 public:
  // An empty segmentation on the volume's grid, with no undo history.
  void reset(const Volume& v);
  // S (from a session) on volume V; throws an input Error when S is not on V's grid or is
  // inconsistent (segmentation_check.h), and keeps what it had then.
  void load(Segmentation s, const Volume& v);
  void clear();  // no volume: nothing to segment
  bool active() const { return active_; }
  const Segmentation& segmentation() const { return s_; }

  // The segment list. Each edit is one undo step; a label that names no segment throws an
  // input Error.
  uint8_t addSegment(const std::string& name, glm::vec3 colour);  // the lowest free label
  void removeSegment(uint8_t label);                              // and its voxels
  void rename(uint8_t label, const std::string& name);
  void setColour(uint8_t label, glm::vec3 colour);
  void setOpacity(uint8_t label, float opacity);  // clamped to 0..1
  void setVisible(uint8_t label, bool visible);
  void setCodes(uint8_t label, const Segment::Code& category, const Segment::Code& type);

  // Label edits, each one undo step (none when nothing changed).
  void paintSphere(glm::dvec3 centre, double radiusMm, uint8_t label, EditPolicy p = {});
  void eraseSphere(glm::dvec3 centre, double radiusMm, uint8_t label);
  void paintDisc(int axis, glm::dvec3 centre, double radiusMm, uint8_t label, EditPolicy p = {});
  void eraseDisc(int axis, glm::dvec3 centre, double radiusMm, uint8_t label);
  void setMask(uint8_t label, const Mask& m, const std::string& what, EditPolicy p = {});
  // The recipe voxray-cli segment runs, into `label`.
  void applyRecipe(const Volume& v, const SegmentRecipe& r, uint8_t label, EditPolicy p = {});

  bool canUndo() const { return done_ > 0; }
  bool canRedo() const { return done_ < steps_.size(); }
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
  void push(std::string what, LabelPatch patch, std::vector<Segment> before);
  void swap(Step& step);

  Segmentation s_;
  bool active_ = false;
  std::vector<Step> steps_;
  size_t done_ = 0;  // steps_[0, done_) are done; the rest undone (redo)
};

}  // namespace voxray
