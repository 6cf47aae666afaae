#include "view_history.h"

namespace voxray {

namespace {
bool sameCamera(const CameraParams& a, const CameraParams& b) {
  return a.azimuthDeg == b.azimuthDeg && a.elevationDeg == b.elevationDeg && a.zoom == b.zoom &&
         a.distanceMm == b.distanceMm && a.panMm == b.panMm && a.projection == b.projection &&
         a.fovDeg == b.fovDeg;
}
bool sameLight(const LightParams& a, const LightParams& b) {
  return a.position == b.position && a.followCamera == b.followCamera && a.ambient == b.ambient &&
         a.diffuse == b.diffuse && a.specular == b.specular && a.shininess == b.shininess;
}
bool sameSlabs(const std::array<Slab, 3>& a, const std::array<Slab, 3>& b) {
  for (size_t o = 0; o < a.size(); ++o)
    if (a[o].thicknessMm != b[o].thicknessMm || a[o].mode != b[o].mode) return false;
  return true;
}
}  // namespace

ViewSnapshot takeViewSnapshot(const AppModels& m) {
  const RenderParams& p = m.render.params();
  ViewSnapshot s{p.camera,
                 p.clip,
                 p.light,
                 p.windowWidth,
                 p.windowLevel,
                 m.windowLevel.value(),
                 m.windowLevel.source()};
  for (size_t o = 0; o < s.planes.size(); ++o) {
    s.planes[o] = m.crosshair.rotation(Orientation(o));
    s.slabs[o] = m.crosshair.slab(Orientation(o));
  }
  s.segmentTfs = p.segmentTfs;
  return s;
}

bool sameView(const ViewSnapshot& a, const ViewSnapshot& b) {
  return sameCamera(a.camera, b.camera) && a.clip.lo == b.clip.lo && a.clip.hi == b.clip.hi &&
         sameLight(a.light, b.light) && a.mipWidth == b.mipWidth && a.mipLevel == b.mipLevel &&
         a.wl.width == b.wl.width && a.wl.level == b.wl.level && a.wlSource == b.wlSource &&
         a.planes == b.planes && sameSlabs(a.slabs, b.slabs) && a.segmentTfs == b.segmentTfs;
}

ViewHistory::ViewHistory(AppModels& m) : m_(m), current_(takeViewSnapshot(m)) {
  renderConnection_ = m_.render.changed.connect([this](unsigned) { onChange(); });
  wlConnection_ = m_.windowLevel.changed.connect([this] { onChange(); });
  docConnection_ = m_.document.changed.connect([this] { restart(); });
  crosshairConnection_ = m_.crosshair.changed.connect([this] { onChange(); });
}

ViewHistory::~ViewHistory() {
  m_.render.changed.disconnect(renderConnection_);
  m_.windowLevel.changed.disconnect(wlConnection_);
  m_.document.changed.disconnect(docConnection_);
  m_.crosshair.changed.disconnect(crosshairConnection_);
}

void ViewHistory::beginGesture() {
  inGesture_ = true;
  gestureRecorded_ = false;
}

void ViewHistory::endGesture() { inGesture_ = false; }

void ViewHistory::onChange() {
  if (applying_) return;
  ViewSnapshot now = takeViewSnapshot(m_);
  if (sameView(now, current_)) return;
  // A gesture's first change records where it started; its later changes only move on.
  if (!inGesture_ || !gestureRecorded_) {
    undo_.push_back(current_);
    if (undo_.size() > kLimit) undo_.erase(undo_.begin());
    redo_.clear();
    gestureRecorded_ = inGesture_;
  }
  current_ = now;
  changed.notify();
}

void ViewHistory::restart() {
  undo_.clear();
  redo_.clear();
  current_ = takeViewSnapshot(m_);
  changed.notify();
}

void ViewHistory::apply(const ViewSnapshot& s) {
  applying_ = true;
  m_.render.update(kCamera | kClip | kLight | kAppearance, [&](RenderParams& p) {
    p.camera = s.camera;
    p.clip = s.clip;
    p.light = s.light;
    p.windowWidth = s.mipWidth;
    p.windowLevel = s.mipLevel;
    p.segmentTfs = s.segmentTfs;
  });
  // The window with where it came from: set() would leave "DICOM window 1" behind.
  const WindowLevel& wl = m_.windowLevel.value();
  if (wl.width != s.wl.width || wl.level != s.wl.level || m_.windowLevel.source() != s.wlSource)
    m_.windowLevel.reset(s.wl, s.wlSource);
  // The planes turn back about where the crosshair is now (its position is not recorded).
  for (size_t o = 0; o < s.slabs.size(); ++o) m_.crosshair.setSlab(Orientation(o), s.slabs[o]);
  m_.crosshair.setPlanes(m_.crosshair.centre(), s.planes);
  applying_ = false;
  current_ = takeViewSnapshot(m_);
  changed.notify();
}

void ViewHistory::step(std::vector<ViewSnapshot>& from, std::vector<ViewSnapshot>& to) {
  if (from.empty()) return;
  to.push_back(current_);
  ViewSnapshot s = from.back();
  from.pop_back();
  apply(s);
}

void ViewHistory::undo() { step(undo_, redo_); }

void ViewHistory::redo() { step(redo_, undo_); }

}  // namespace voxray
