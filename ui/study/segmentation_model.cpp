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

LabelPatch copyLabels(const Segmentation& s, glm::ivec3 lo, glm::ivec3 hi) {
  LabelPatch p{lo, hi, {}};
  p.labels.reserve(size_t(hi.x - lo.x) * size_t(hi.y - lo.y) * size_t(hi.z - lo.z));
  for (int z = lo.z; z < hi.z; ++z)
    for (int y = lo.y; y < hi.y; ++y)
      for (int x = lo.x; x < hi.x; ++x) p.labels.push_back(s.labels[s.grid.index(x, y, z)]);
  return p;
}

void SegmentationModel::touched(const LabelPatch& p) {
  if (p.empty() || edits_.whole) return;
  if (!edits_.any) {
    edits_.any = true;
    edits_.lo = p.lo;
    edits_.hi = p.hi;
    return;
  }
  edits_.lo = glm::min(edits_.lo, p.lo);
  edits_.hi = glm::max(edits_.hi, p.hi);
}

void SegmentationModel::touchedAll() {
  edits_ = {};
  edits_.whole = true;
}

void SegmentationModel::beginStroke() {
  inStroke_ = true;
  strokeStep_ = false;
}

void SegmentationModel::endStroke() {
  inStroke_ = false;
  strokeStep_ = false;
}

void SegmentationModel::reset(const Volume& v) {
  s_ = std::make_shared<Segmentation>(emptySegmentation(v));
  active_ = true;
  steps_.clear();
  done_ = 0;
  touchedAll();
  changed.notify();
}

void SegmentationModel::load(Segmentation s, const Volume& v) {
  checkSegmentation(s);
  checkSameGrid(s, v);
  s_ = std::make_shared<Segmentation>(std::move(s));
  active_ = true;
  steps_.clear();
  done_ = 0;
  touchedAll();
  changed.notify();
}

void SegmentationModel::clear() {
  s_ = std::make_shared<Segmentation>();
  active_ = false;
  steps_.clear();
  done_ = 0;
  touchedAll();
  changed.notify();
}

Segmentation& SegmentationModel::mut() {
  // Copy on write: a snapshot still held elsewhere (the statistics counting on the pool, the
  // render worker's pending update) keeps the labels it took; the model edits its own copy.
  if (s_.use_count() > 1) s_ = std::make_shared<Segmentation>(*s_);
  return *s_;
}

Segment& SegmentationModel::segment(uint8_t label) {
  for (auto& seg : mut().segments)
    if (seg.label == label) return seg;
  throw inputError("There is no segment with label " + std::to_string(label) + ".");
}

void SegmentationModel::push(std::string what, LabelPatch patch, std::vector<Segment> before) {
  touched(patch);
  if (inStroke_ && strokeStep_ && done_ == steps_.size() && !patch.empty()) {
    // The stroke's step takes this dab: its patch becomes the labels before the stroke over
    // both boxes. Swapping both patches out gives the map before the stroke, to copy.
    Step& a = steps_.back();
    const glm::ivec3 lo = glm::min(a.patch.lo, patch.lo), hi = glm::max(a.patch.hi, patch.hi);
    swapPatch(mut(), patch);
    swapPatch(mut(), a.patch);
    LabelPatch merged = copyLabels(mut(), lo, hi);
    swapPatch(mut(), a.patch);
    swapPatch(mut(), patch);
    a.patch = std::move(merged);
    changed.notify();
    return;
  }
  strokeStep_ = inStroke_ && !patch.empty();
  steps_.resize(done_);  // a new edit drops what could be redone
  steps_.push_back({std::move(what), std::move(patch), std::move(before)});
  if (steps_.size() > kMaxSteps) steps_.erase(steps_.begin());
  done_ = steps_.size();
  changed.notify();
}

void SegmentationModel::swap(Step& step) {
  strokeStep_ = false;
  touched(step.patch);
  swapPatch(mut(), step.patch);
  std::swap(mut().segments, step.segments);
}

uint8_t SegmentationModel::addSegment(const std::string& name, glm::vec3 colour) {
  if (!active_) throw inputError("Open a volume before adding a segment.");
  std::array<bool, 256> used{};
  for (const auto& seg : mut().segments) used[seg.label] = true;
  int label = 1;
  while (label < 256 && used[size_t(label)]) ++label;
  if (label == 256)
    throw inputError(
        "This segmentation holds 255 segments, the most a label map can: remove "
        "one before adding another.");
  auto before = mut().segments;
  Segment seg;
  seg.label = uint8_t(label);
  seg.name = name;
  seg.colour = glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f));
  mut().segments.push_back(seg);
  push("Add segment", {}, std::move(before));
  return uint8_t(label);
}

void SegmentationModel::removeSegment(uint8_t label) {
  segment(label);
  auto before = mut().segments;
  // Its voxels become background, in the same step.
  LabelPatch patch = voxray::setMask(mut(), label, Mask(mut().labels.size(), 0), EditPolicy{});
  std::erase_if(mut().segments, [&](const Segment& s) { return s.label == label; });
  push("Remove segment", std::move(patch), std::move(before));
}

void SegmentationModel::rename(uint8_t label, const std::string& name) {
  auto before = mut().segments;
  segment(label).name = name;
  push("Rename segment", {}, std::move(before));
}

void SegmentationModel::setColour(uint8_t label, glm::vec3 colour) {
  auto before = mut().segments;
  segment(label).colour = glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f));
  push("Segment colour", {}, std::move(before));
}

void SegmentationModel::setOpacity(uint8_t label, float opacity) {
  auto before = mut().segments;
  segment(label).opacity = std::clamp(opacity, 0.0f, 1.0f);
  push("Segment opacity", {}, std::move(before));
}

void SegmentationModel::setVisible(uint8_t label, bool visible) {
  auto before = mut().segments;
  segment(label).visible = visible;
  push(visible ? "Show segment" : "Hide segment", {}, std::move(before));
}

void SegmentationModel::setDisplay3d(uint8_t label, Segment::Display3d display) {
  auto before = mut().segments;
  Segment& seg = segment(label);
  if (seg.display3d == display) return;  // no step for nothing
  seg.display3d = display;
  push("Segment 3D display", {}, std::move(before));
}

void SegmentationModel::setCodes(uint8_t label, const Segment::Code& category,
                                 const Segment::Code& type) {
  auto before = mut().segments;
  Segment& seg = segment(label);
  seg.category = category;
  seg.type = type;
  push("Segment category", {}, std::move(before));
}

void SegmentationModel::paintSphere(glm::dvec3 centre, double radiusMm, uint8_t label,
                                    EditPolicy p) {
  LabelPatch patch = voxray::paintSphere(mut(), centre, radiusMm, label, p);
  if (!patch.empty()) push("Paint", std::move(patch), mut().segments);
}

void SegmentationModel::eraseSphere(glm::dvec3 centre, double radiusMm, uint8_t label) {
  LabelPatch patch = voxray::eraseSphere(mut(), centre, radiusMm, label);
  if (!patch.empty()) push("Erase", std::move(patch), mut().segments);
}

void SegmentationModel::paintDisc(int axis, glm::dvec3 centre, double radiusMm, uint8_t label,
                                  EditPolicy p) {
  LabelPatch patch = voxray::paintDisc(mut(), axis, centre, radiusMm, label, p);
  if (!patch.empty()) push("Paint", std::move(patch), mut().segments);
}

void SegmentationModel::eraseDisc(int axis, glm::dvec3 centre, double radiusMm, uint8_t label) {
  LabelPatch patch = voxray::eraseDisc(mut(), axis, centre, radiusMm, label);
  if (!patch.empty()) push("Erase", std::move(patch), mut().segments);
}

void SegmentationModel::setMask(uint8_t label, const Mask& m, const std::string& what,
                                EditPolicy p) {
  LabelPatch patch = voxray::setMask(mut(), label, m, p);
  if (!patch.empty()) push(what, std::move(patch), mut().segments);
}

void SegmentationModel::applyRecipe(const Volume& v, const SegmentRecipe& r, uint8_t label,
                                    EditPolicy p) {
  checkSameGrid(*s_, v);
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
