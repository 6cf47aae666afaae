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
  if (target_ != 0) {  // the segment's table chosen elsewhere (the panel, undo), or the volume's
    auto it = p.segmentTfs.find(target_);
    const bool own = it != p.segmentTfs.end();
    VolumeProperty start = volumeProperty();
    start.tf2d = {};
    if (own != segmentOwnsTable() || (own && it->second != renderTable(vp_)) ||
        (!own && !(vp_ == start)))
      takeFromView();
    return;
  }
  if (!p.preset.empty() || p.presetShiftHu != 0.0 || p.opacityUnitMm != vp_.unitDistanceMm ||
      p.transferFunction != renderTable(vp_) || p.tf2d != vp_.tf2d)
    takeFromView();
}

VolumeProperty TfEditorModel::volumeProperty() const {
  // In iso or mip the table is not the dvr's: start from what dvr would show.
  RenderParams p = render_.params();
  if (p.mode != Mode::Dvr) {
    p.mode = Mode::Dvr;
    if (!p.preset.empty() && !presetFitsMode(p.preset, Mode::Dvr)) p.preset.clear();
  }
  // The editor's own lists and curve where the view still shows them (a session brings them).
  std::optional<VolumeProperty> shaped = render_.shapedTransferFunction();
  return shaped ? *shaped : volumePropertyOf(p);
}

void TfEditorModel::setTarget(uint8_t label) {
  target_ = label;
  takeFromView();
}

void TfEditorModel::takeFromView() {
  vp_ = volumeProperty();
  startedOwn_ = false;
  if (target_ != 0) {
    const RenderParams& p = render_.params();
    if (auto it = p.segmentTfs.find(target_); it != p.segmentTfs.end()) {
      // The segment's table read back as a property (linear, at its points).
      RenderParams own;
      own.mode = Mode::Dvr;
      own.transferFunction = it->second;
      vp_ = volumePropertyOf(own);
      startedOwn_ = true;
    }
    vp_.tf2d = {};  // segments have 1D tables only
  }
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

size_t TfEditorModel::addTf2dPrimitive(const Tf2dPrimitive& prim, double axisTop) {
  if (vp_.tf2d.primitives.size() >= kMaxTf2dPrimitives) return vp_.tf2d.primitives.size() - 1;
  Tf2dPrimitive q = prim;
  q.hu1 = std::max(q.hu1, q.hu0 + kTf2dMinHu);
  q.g0 = std::max(0.0, q.g0);
  q.g1 = std::max(q.g1, q.g0 + kTf2dMinG);
  q.rgb = glm::clamp(q.rgb, 0.0, 1.0);
  q.opacity = std::clamp(q.opacity, 0.0, 1.0);
  q.soft = std::clamp(q.soft, 0.0, 1.0);
  edit([&](VolumeProperty& p) {
    if (p.tf2d.empty() && axisTop > 0.0 && std::isfinite(axisTop)) p.tf2d.gradientMax = axisTop;
    p.tf2d.primitives.push_back(q);
  });
  return vp_.tf2d.primitives.size() - 1;
}

void TfEditorModel::moveTf2dPrimitive(size_t i, double dHu, double dG) {
  if (i >= vp_.tf2d.primitives.size() || !std::isfinite(dHu) || !std::isfinite(dG)) return;
  edit([&](VolumeProperty& p) { p.tf2d.primitives[i] = tf2dMoved(p.tf2d.primitives[i], dHu, dG); });
}

void TfEditorModel::resizeTf2dPrimitive(size_t i, Tf2dPart corner, double hu, double g) {
  if (i >= vp_.tf2d.primitives.size() || !std::isfinite(hu) || !std::isfinite(g)) return;
  edit([&](VolumeProperty& p) {
    p.tf2d.primitives[i] = tf2dResized(p.tf2d.primitives[i], corner, hu, g);
  });
}

void TfEditorModel::setTf2dExtent(size_t i, double hu0, double hu1, double g0, double g1) {
  if (i >= vp_.tf2d.primitives.size()) return;
  for (double x : {hu0, hu1, g0, g1})
    if (!std::isfinite(x)) return;
  edit([&](VolumeProperty& p) {
    Tf2dPrimitive& q = p.tf2d.primitives[i];
    q.hu0 = hu0;
    q.hu1 = std::max(hu1, hu0 + kTf2dMinHu);
    q.g0 = std::max(0.0, g0);
    q.g1 = std::max(g1, q.g0 + kTf2dMinG);
  });
}

void TfEditorModel::setTf2dColor(size_t i, glm::dvec3 rgb) {
  if (i >= vp_.tf2d.primitives.size()) return;
  edit([&](VolumeProperty& p) { p.tf2d.primitives[i].rgb = glm::clamp(rgb, 0.0, 1.0); });
}

void TfEditorModel::setTf2dOpacity(size_t i, double opacity) {
  if (i >= vp_.tf2d.primitives.size() || !std::isfinite(opacity)) return;
  edit([&](VolumeProperty& p) { p.tf2d.primitives[i].opacity = std::clamp(opacity, 0.0, 1.0); });
}

void TfEditorModel::setTf2dSoft(size_t i, double soft) {
  if (i >= vp_.tf2d.primitives.size() || !std::isfinite(soft)) return;
  edit([&](VolumeProperty& p) { p.tf2d.primitives[i].soft = std::clamp(soft, 0.0, 1.0); });
}

void TfEditorModel::removeTf2dPrimitive(size_t i) {
  if (i >= vp_.tf2d.primitives.size()) return;
  edit([&](VolumeProperty& p) {
    p.tf2d.primitives.erase(p.tf2d.primitives.begin() + long(i));
    if (p.tf2d.empty()) p.tf2d.gradientMax = 0.0;
  });
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
  if (target_ != 0) {
    const bool own = segmentOwnsTable();
    render_.update(kAppearance, [&](RenderParams& p) {
      if (own)
        p.segmentTfs[target_] = renderTable(vp_);
      else
        p.segmentTfs.erase(target_);
    });
  } else {
    render_.setShapedTransferFunction(vp_);
    render_.update(kAppearance, [&](RenderParams& p) { applyVolumeProperty(p, vp_); });
  }
  showing_ = false;
  changed.notify();
}

}  // namespace voxray
