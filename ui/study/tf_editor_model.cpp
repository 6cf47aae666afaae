#include "tf_editor_model.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace voxray {

namespace {

constexpr size_t kUndoLimit = 200;

// HU clamped between the neighbours of point I of a list of N (positions by POS).
template <class List, class Pos>
double between(const List& list, size_t i, double hu, Pos pos) {
  if (i > 0) hu = std::max(hu, pos(list[i - 1]));
  if (i + 1 < list.size()) hu = std::min(hu, pos(list[i + 1]));
  return hu;
}

template <class List, class Node, class Pos>
size_t insertSorted(List& list, Node node, Pos pos) {
  auto at = std::upper_bound(list.begin(), list.end(), pos(node),
                             [&](double h, const Node& n) { return h < pos(n); });
  return size_t(std::distance(list.begin(), list.insert(at, node)));
}

double huOf(const ColorNode& n) { return n.hu; }
double xOf(const OpacityNode& n) { return n.x; }

}  // namespace

TfEditorModel::TfEditorModel(RenderStateModel& render) : render_(render) {
  takeFromView();
  listener_ = render_.changed.connect([this](unsigned what) { viewChanged(what); });
}

TfEditorModel::~TfEditorModel() { render_.changed.disconnect(listener_); }

void TfEditorModel::viewChanged(unsigned what) {
  if (showing_ || !(what & kAppearance)) return;
  const RenderParams& p = render_.params();
  if (p.mode != Mode::Dvr) return;
  if (!p.preset.empty() || p.presetShiftHu != 0.0 || p.opacityUnitMm != vp_.unitDistanceMm ||
      p.transferFunction != renderTable(vp_))
    takeFromView();
}

void TfEditorModel::takeFromView() {
  // In iso or mip the table is not the dvr's: start from what dvr would show.
  RenderParams p = render_.params();
  if (p.mode != Mode::Dvr) {
    p.mode = Mode::Dvr;
    if (!p.preset.empty() && !presetFitsMode(p.preset, Mode::Dvr)) p.preset.clear();
  }
  // The editor's own lists and curve where the view still shows them (a session brings them).
  std::optional<VolumeProperty> shaped = render_.shapedTransferFunction();
  vp_ = shaped ? *shaped : volumePropertyOf(p);
  undo_.clear();
  redo_.clear();
  changed.notify();
}

void TfEditorModel::setProperty(const VolumeProperty& vp) {
  edit([&](VolumeProperty& p) { p = vp; });
}

size_t TfEditorModel::addOpacityPoint(double hu, double opacity) {
  size_t index = 0;
  edit([&](VolumeProperty& p) {
    index = insertSorted(p.opacity, OpacityNode{hu, std::clamp(opacity, 0.0, 1.0)}, xOf);
  });
  return index;
}

void TfEditorModel::moveOpacityPoint(size_t i, double hu, double opacity) {
  if (i >= vp_.opacity.size()) return;
  edit([&](VolumeProperty& p) {
    p.opacity[i] = {between(p.opacity, i, hu, xOf), std::clamp(opacity, 0.0, 1.0)};
  });
}

void TfEditorModel::removeOpacityPoint(size_t i) {
  if (i >= vp_.opacity.size() || vp_.opacity.size() < 2) return;
  edit([&](VolumeProperty& p) { p.opacity.erase(p.opacity.begin() + long(i)); });
}

size_t TfEditorModel::addColorPoint(double hu) {
  size_t index = 0;
  glm::dvec3 rgb = colorAt(vp_, hu);
  edit([&](VolumeProperty& p) { index = insertSorted(p.color, ColorNode{hu, rgb}, huOf); });
  return index;
}

void TfEditorModel::moveColorPoint(size_t i, double hu) {
  if (i >= vp_.color.size()) return;
  edit([&](VolumeProperty& p) { p.color[i].hu = between(p.color, i, hu, huOf); });
}

void TfEditorModel::setPointColor(size_t i, glm::dvec3 rgb) {
  if (i >= vp_.color.size()) return;
  edit([&](VolumeProperty& p) { p.color[i].rgb = glm::clamp(rgb, 0.0, 1.0); });
}

void TfEditorModel::removeColorPoint(size_t i) {
  if (i >= vp_.color.size() || vp_.color.size() < 2) return;
  edit([&](VolumeProperty& p) { p.color.erase(p.color.begin() + long(i)); });
}

void TfEditorModel::setCurve(TfCurve curve) {
  edit([&](VolumeProperty& p) { p.curve = curve; });
}

void TfEditorModel::setUnitDistance(double mm) {
  if (!std::isfinite(mm)) return;
  edit([&](VolumeProperty& p) { p.unitDistanceMm = std::max(0.0, mm); });
}

void TfEditorModel::beginGesture() {
  if (gesture_++ == 0) gestureRecorded_ = false;
}

void TfEditorModel::endGesture() {
  if (gesture_ > 0) --gesture_;
}

void TfEditorModel::undo() {
  if (undo_.empty()) return;
  redo_.push_back(vp_);
  vp_ = undo_.back();
  undo_.pop_back();
  show();
}

void TfEditorModel::redo() {
  if (redo_.empty()) return;
  undo_.push_back(vp_);
  vp_ = redo_.back();
  redo_.pop_back();
  show();
}

void TfEditorModel::edit(const std::function<void(VolumeProperty&)>& change) {
  VolumeProperty next = vp_;
  change(next);
  if (next == vp_) return;
  // One step per edit, or per gesture: its first edit records the state before it.
  if (gesture_ == 0 || !gestureRecorded_) {
    undo_.push_back(vp_);
    if (undo_.size() > kUndoLimit) undo_.erase(undo_.begin());
    redo_.clear();
    gestureRecorded_ = gesture_ > 0;
  }
  vp_ = std::move(next);
  show();
}

void TfEditorModel::show() {
  showing_ = true;
  render_.setShapedTransferFunction(vp_);
  render_.update(kAppearance, [&](RenderParams& p) { applyVolumeProperty(p, vp_); });
  showing_ = false;
  changed.notify();
}

}  // namespace voxray
