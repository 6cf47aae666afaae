#pragma once
// Text and arrow annotations of the slice views (issue 37) as data. Unlike measurements
// (voxel positions) an annotation is kept in patient space, LPS mm, so that it names the
// same place whatever grid shows it: a text's anchor, or an arrow's head and tail. Each one
// remembers the plane it was made on (its normal) and shows on the views of that plane whose
// slice lies within half a slice spacing of it. Every add, edit and delete is one undo step.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "notifier.h"

namespace voxray {

struct Volume;
struct SliceAxes;

struct Annotation {
  int id = 0;
  std::string text;                  // an arrow's may be empty
  glm::dvec3 anchorMm{0.0};          // LPS: the text's point, or the arrow's head
  std::optional<glm::dvec3> tailMm;  // LPS: an arrow's tail; none for a text
  glm::dvec3 normal{0.0, 0.0, 1.0};  // LPS unit normal of the plane it was made on
  bool isArrow() const { return tailMm.has_value(); }
  bool operator==(const Annotation& o) const {
    return id == o.id && text == o.text && anchorMm == o.anchorMm && tailMm == o.tailMm &&
           normal == o.normal;
  }
};

// Whether A shows on the view plane through POINTMM with unit NORMAL and slice SPACINGMM: the
// planes are parallel (within a degree, a plane made on one view and shown on its twin) and
// every point of A lies within half a slice of the view's plane.
bool annotationOnPlane(const Annotation& a, const glm::dvec3& normal, const glm::dvec3& pointMm,
                       double spacingMm);
// The same for an acquisition-plane slice view (AXES at SLICE) of V.
bool annotationOnSlice(const Annotation& a, const Volume& v, const SliceAxes& axes, int slice);
// The LPS normal of an acquisition-plane view of V (the direction column of AXES' normal).
glm::dvec3 sliceNormal(const Volume& v, const SliceAxes& axes);

class AnnotationModel {
 public:
  const std::vector<Annotation>& items() const { return items_; }
  const Annotation* find(int id) const;
  // Each is one undo step and selects the annotation; they return its id.
  int addText(const std::string& text, const glm::dvec3& anchorMm, const glm::dvec3& normal);
  int addArrow(const glm::dvec3& headMm, const glm::dvec3& tailMm, const glm::dvec3& normal,
               const std::string& text = {});
  void setText(int id, const std::string& text);  // one undo step; nothing when unchanged
  void remove(int id);                            // one undo step
  // Removes everything (a new volume) and forgets the history: it belonged to the old one.
  void clear();
  // Replaces everything with ITEMS (given fresh ids) and forgets the history (a session read).
  void reset(std::vector<Annotation> items);
  int selected() const { return selected_; }  // 0: none
  void select(int id);

  bool canUndo() const { return done_ > 0; }
  bool canRedo() const { return done_ < history_.size(); }
  size_t undoCount() const { return done_; }
  size_t redoCount() const { return history_.size() - done_; }
  std::string undoText() const;  // "Undo Add arrow", or empty
  std::string redoText() const;
  void undo();
  void redo();

  Notifier<> changed;

 private:
  struct Step {
    std::string what;
    std::vector<Annotation> before, after;
  };
  void commit(const std::string& what, std::vector<Annotation> after);
  std::vector<Annotation> items_;
  std::vector<Step> history_;
  size_t done_ = 0;  // history_[0, done_) are done; the rest undone (redo)
  int nextId_ = 1, selected_ = 0;
};

// Each annotation as a line of a report: "text at (-93.0, 66.0, 37.5) mm: lesion" or
// "arrow from (…) mm to (…) mm: text" (LPS, 0.1 mm), in the list's order.
std::vector<std::string> annotationReportTexts(const AnnotationModel& m);

// The session key "annotations": [{"text": "…", "anchor_mm": [x, y, z], "tail_mm": [x, y, z]
// (arrows only), "normal": [x, y, z]}, …].
nlohmann::json annotationsToJson(const AnnotationModel& m);
// Replaces the model's annotations (no undo history). Throws Error (Input) naming the first bad
// entry; the model is then unchanged.
void annotationsFromJson(const nlohmann::json& j, AnnotationModel& m);

}  // namespace voxray
