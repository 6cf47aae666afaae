#include "segmentation_model.h"

#include <algorithm>
#include <array>

#include "voxray/io/error.h"
#include "voxray/io/segmentation_check.h"

namespace voxray {
namespace {

// The undo history's labels are kept up to this many steps (a step holds a box of labels).
constexpr size_t kMaxSteps = 100;

}  // namespace

void SegmentationModel::reset(const Volume& v) {
  s_ = emptySegmentation(v);
  active_ = true;
  steps_.clear();
  done_ = 0;
  changed.notify();
}

void SegmentationModel::load(Segmentation s, const Volume& v) {
  checkSegmentation(s);
  checkSameGrid(s, v);
  s_ = std::move(s);
  active_ = true;
  steps_.clear();
  done_ = 0;
  changed.notify();
}

void SegmentationModel::clear() {
  s_ = Segmentation{};
  active_ = false;
  steps_.clear();
  done_ = 0;
  changed.notify();
}

Segment& SegmentationModel::segment(uint8_t label) {
  for (auto& seg : s_.segments)
    if (seg.label == label) return seg;
  throw inputError("There is no segment with label " + std::to_string(label) + ".");
}

void SegmentationModel::push(std::string what, LabelPatch patch, std::vector<Segment> before) {
  steps_.resize(done_);  // a new edit drops what could be redone
  steps_.push_back({std::move(what), std::move(patch), std::move(before)});
  if (steps_.size() > kMaxSteps) steps_.erase(steps_.begin());
  done_ = steps_.size();
  changed.notify();
}

void SegmentationModel::swap(Step& step) {
  swapPatch(s_, step.patch);
  std::swap(s_.segments, step.segments);
}

uint8_t SegmentationModel::addSegment(const std::string& name, glm::vec3 colour) {
  if (!active_) throw inputError("Open a volume before adding a segment.");
  std::array<bool, 256> used{};
  for (const auto& seg : s_.segments) used[seg.label] = true;
  int label = 1;
  while (label < 256 && used[size_t(label)]) ++label;
  if (label == 256)
    throw inputError(
        "This segmentation holds 255 segments, the most a label map can: remove "
        "one before adding another.");
  auto before = s_.segments;
  Segment seg;
  seg.label = uint8_t(label);
  seg.name = name;
  seg.colour = glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f));
  s_.segments.push_back(seg);
  push("Add segment", {}, std::move(before));
  return uint8_t(label);
}

void SegmentationModel::removeSegment(uint8_t label) {
  segment(label);
  auto before = s_.segments;
  // Its voxels become background, in the same step.
  LabelPatch patch = voxray::setMask(s_, label, Mask(s_.labels.size(), 0), EditPolicy{});
  std::erase_if(s_.segments, [&](const Segment& s) { return s.label == label; });
  push("Remove segment", std::move(patch), std::move(before));
}

void SegmentationModel::rename(uint8_t label, const std::string& name) {
  auto before = s_.segments;
  segment(label).name = name;
  push("Rename segment", {}, std::move(before));
}

void SegmentationModel::setColour(uint8_t label, glm::vec3 colour) {
  auto before = s_.segments;
  segment(label).colour = glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f));
  push("Segment colour", {}, std::move(before));
}

void SegmentationModel::setOpacity(uint8_t label, float opacity) {
  auto before = s_.segments;
  segment(label).opacity = std::clamp(opacity, 0.0f, 1.0f);
  push("Segment opacity", {}, std::move(before));
}

void SegmentationModel::setVisible(uint8_t label, bool visible) {
  auto before = s_.segments;
  segment(label).visible = visible;
  push(visible ? "Show segment" : "Hide segment", {}, std::move(before));
}

void SegmentationModel::setCodes(uint8_t label, const Segment::Code& category,
                                 const Segment::Code& type) {
  auto before = s_.segments;
  Segment& seg = segment(label);
  seg.category = category;
  seg.type = type;
  push("Segment category", {}, std::move(before));
}

void SegmentationModel::paintSphere(glm::dvec3 centre, double radiusMm, uint8_t label,
                                    EditPolicy p) {
  LabelPatch patch = voxray::paintSphere(s_, centre, radiusMm, label, p);
  if (!patch.empty()) push("Paint", std::move(patch), s_.segments);
}

void SegmentationModel::eraseSphere(glm::dvec3 centre, double radiusMm, uint8_t label) {
  LabelPatch patch = voxray::eraseSphere(s_, centre, radiusMm, label);
  if (!patch.empty()) push("Erase", std::move(patch), s_.segments);
}

void SegmentationModel::paintDisc(int axis, glm::dvec3 centre, double radiusMm, uint8_t label,
                                  EditPolicy p) {
  LabelPatch patch = voxray::paintDisc(s_, axis, centre, radiusMm, label, p);
  if (!patch.empty()) push("Paint", std::move(patch), s_.segments);
}

void SegmentationModel::eraseDisc(int axis, glm::dvec3 centre, double radiusMm, uint8_t label) {
  LabelPatch patch = voxray::eraseDisc(s_, axis, centre, radiusMm, label);
  if (!patch.empty()) push("Erase", std::move(patch), s_.segments);
}

void SegmentationModel::setMask(uint8_t label, const Mask& m, const std::string& what,
                                EditPolicy p) {
  LabelPatch patch = voxray::setMask(s_, label, m, p);
  if (!patch.empty()) push(what, std::move(patch), s_.segments);
}

void SegmentationModel::applyRecipe(const Volume& v, const SegmentRecipe& r, uint8_t label,
                                    EditPolicy p) {
  checkSameGrid(s_, v);
  setMask(label, runRecipe(v, r), "Threshold", p);
}

std::string SegmentationModel::undoText() const {
  return canUndo() ? "Undo " + steps_[done_ - 1].what : std::string();
}

std::string SegmentationModel::redoText() const {
  return canRedo() ? "Redo " + steps_[done_].what : std::string();
}

void SegmentationModel::undo() {
  if (!canUndo()) return;
  swap(steps_[--done_]);
  changed.notify();
}

void SegmentationModel::redo() {
  if (!canRedo()) return;
  swap(steps_[done_++]);
  changed.notify();
}

}  // namespace voxray
