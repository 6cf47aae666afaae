#include "camera_link.h"

#include <algorithm>
#include <cmath>

#include "voxray/io/volume.h"

namespace voxray {

namespace {
// A volume of G's geometry without voxels: makeViewGeometry reads only its geometry.
Volume shell(const VolumeGeometry& g) {
  Volume v;
  v.dims = g.dims;
  v.spacingMm = g.spacingMm;
  v.originMm = g.originMm;
  v.direction = g.direction;
  return v;
}

ViewGeometry engineView(const CameraParams& camera, const VolumeGeometry& g) {
  RenderParams p;
  p.camera = camera;
  return makeViewGeometry(shell(g), p);
}

double radiusMm(const VolumeGeometry& g) {
  return 0.5 * glm::length(glm::dvec3(g.dims) * g.spacingMm);
}

// Below this cos(elevation) the view looks straight up or down: the azimuth then comes from
// the right vector (the engine keeps it horizontal, so it is defined there too).
constexpr double kPoleCos = 1e-12;
}  // namespace

glm::dvec3 volumeCentreMm(const VolumeGeometry& g) {
  return g.patientOf((glm::dvec3(g.dims) - 1.0) * 0.5);
}

PatientView patientView(const CameraParams& camera, const VolumeGeometry& g) {
  PatientView v;
  v.engine = engineView(camera, g);
  const glm::dvec3 c = volumeCentreMm(g);
  v.eyeMm = c + v.engine.eye;
  v.lookAtMm = c + v.engine.right * camera.panMm.x + v.engine.up * camera.panMm.y;
  v.forward = v.engine.forward;
  v.right = v.engine.right;
  v.up = v.engine.up;
  return v;
}

CameraParams linkedCamera(const CameraParams& camera, const VolumeGeometry& from,
                          const VolumeGeometry& to, const glm::dmat4& fromToTo) {
  const PatientView a = patientView(camera, from);
  const glm::dmat3 r(fromToTo);
  const glm::dvec3 f = glm::normalize(r * a.forward);
  CameraParams out = camera;
  const double el = std::asin(std::clamp(-f.z, -1.0, 1.0));
  out.elevationDeg = glm::degrees(el);
  const glm::dvec3 right = r * a.right;
  out.azimuthDeg =
      glm::degrees(std::cos(el) > kPoleCos ? std::atan2(-f.x, f.y) : std::atan2(right.y, right.x));
  // The new direction's axes as the engine makes them (pan and depth are along these).
  out.panMm = glm::dvec2(0.0);
  out.distanceMm = 0.0;
  const PatientView b = patientView(out, to);
  const glm::dvec3 lookAt(fromToTo * glm::dvec4(a.lookAtMm, 1.0));
  const glm::dvec3 eye(fromToTo * glm::dvec4(a.eyeMm, 1.0));
  const glm::dvec3 rel = lookAt - volumeCentreMm(to);
  out.panMm = {glm::dot(rel, b.right), glm::dot(rel, b.up)};
  const glm::dvec3 target = volumeCentreMm(to) + b.right * out.panMm.x + b.up * out.panMm.y;
  if (camera.projection == Projection::Orthographic) {
    // Parallel rays: the same lines need the same millimetres across the view, which the
    // engine ties to the volume's radius; the eye stays where the engine puts it (outside).
    out.zoom = camera.zoom * radiusMm(to) / radiusMm(from);
    out.distanceMm =
        camera.distanceMm > 0.0 ? std::max(glm::dot(target - eye, b.forward), 1e-3) : 0.0;
  } else {
    // The eye at the mapped eye: its distance to the look-at point in the centre plane. An
    // eye beyond that plane (a camera inside the other volume) cannot be had: the nearest.
    out.distanceMm = std::max(glm::dot(target - eye, b.forward), 1e-3);
  }
  return out;
}

RenderLink::RenderLink(ComparisonModel& model, RenderStateModel& fixed, RenderStateModel& moving)
    : model_(model), fixed_(fixed), moving_(moving) {
  fixedConn_ = fixed_.changed.connect([this](unsigned w) { follow(fixed_, moving_, true, w); });
  movingConn_ = moving_.changed.connect([this](unsigned w) { follow(moving_, fixed_, false, w); });
  modelConn_ = model_.changed.connect([this] { syncMovingToFixed(); });
}

RenderLink::~RenderLink() {
  fixed_.changed.disconnect(fixedConn_);
  moving_.changed.disconnect(movingConn_);
  model_.changed.disconnect(modelConn_);
}

void RenderLink::setLookLinked(bool on) {
  lookLinked_ = on;
  if (on) follow(fixed_, moving_, true, kAppearance | kLight | kQuality);
}

void RenderLink::syncMovingToFixed() {
  follow(fixed_, moving_, true, kCamera | (lookLinked_ ? kAppearance | kLight | kQuality : 0u));
}

void RenderLink::follow(RenderStateModel& leader, RenderStateModel& follower, bool fixedLeads,
                        unsigned what) {
  if (busy_) return;
  const bool look = lookLinked_ && (what & (kAppearance | kLight | kQuality));
  const bool camera = model_.linked() && (what & kCamera) && model_.fixed().dims.x > 0 &&
                      model_.moving().dims.x > 0;
  if (!look && !camera) return;
  busy_ = true;  // the follower's change must not turn the leader back (rounding would drift)
  if (look && (what & kQuality)) follower.setQuality(leader.quality());
  unsigned changed = look ? what & (kAppearance | kLight) : 0u;
  RenderParams next = follower.params();
  if (look) {
    const CameraParams ownCamera = next.camera;
    const ClipBox ownClip = next.clip;
    const SegmentMask ownMask = next.segmentMask;  // the study's segments are not the prior's
    next = leader.params();
    next.segmentMask = ownMask;
    next.camera = ownCamera;
    next.camera.projection = leader.params().camera.projection;
    next.camera.fovDeg = leader.params().camera.fovDeg;
    next.clip = ownClip;
  }
  if (camera) {
    const glm::dmat4 m = fixedLeads ? glm::inverse(model_.movingToFixed()) : model_.movingToFixed();
    next.camera =
        linkedCamera(leader.params().camera, fixedLeads ? model_.fixed() : model_.moving(),
                     fixedLeads ? model_.moving() : model_.fixed(), m);
    changed |= kCamera;
  }
  if (changed) follower.update(changed, [&](RenderParams& p) { p = next; });
  busy_ = false;
}

}  // namespace voxray
