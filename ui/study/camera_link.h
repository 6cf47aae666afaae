#pragma once
// Compare (issue 36): the two columns' 3D views keep one camera in patient coordinates. A
// camera turned or zoomed in one column gives the other column the camera that shows the
// same patient from the same place: the eye at the same patient point and the same view
// direction (both through the alignment transform when there is one), the same angle of view
// (perspective) or the same millimetres across (orthographic). The look (transfer function,
// preset, lighting, quality) follows the other column too unless the user unlinks it.
#include <glm/glm.hpp>

#include "comparison_model.h"
#include "no_qt.h"
#include "render_state_model.h"
#include "voxray/engine/camera.h"

namespace voxray {

// CAMERA's view of a volume of geometry G (the engine's makeViewGeometry) in patient LPS mm:
// the engine's world is LPS with its origin at the volume's centre.
struct PatientView {
  glm::dvec3 eyeMm{0.0}, lookAtMm{0.0};          // LPS mm
  glm::dvec3 forward{0.0}, right{0.0}, up{0.0};  // LPS unit vectors
  ViewGeometry engine;                           // the same view in the engine's world
};
PatientView patientView(const CameraParams& camera, const VolumeGeometry& g);
// G's centre (where the engine's world origin is), LPS mm.
glm::dvec3 volumeCentreMm(const VolumeGeometry& g);

// The camera of volume TO's view that shows what CAMERA shows of volume FROM, where FROMTOTO
// (rigid) maps FROM's patient coordinates onto TO's. The engine's look-at point lies in the
// plane through the volume's centre across the view, so the linked camera's look-at point
// is FROM's mapped point slid along the shared central ray, with the distance that puts the
// eye exactly at FROM's mapped eye. The engine keeps its right vector horizontal (no roll):
// a transform that tilts the view's horizon is followed in direction, not in roll.
CameraParams linkedCamera(const CameraParams& camera, const VolumeGeometry& from,
                          const VolumeGeometry& to, const glm::dmat4& fromToTo);

// Keeps the two columns' render states linked while MODEL says navigation is linked: a camera
// change of either turns the other (linkedCamera through movingToFixed), a change of the look
// (appearance, light, quality) is copied while lookLinked; never echoed back. Clip boxes stay
// each column's own (fractions of different volumes).
class RenderLink {
 public:
  RenderLink(ComparisonModel& model, RenderStateModel& fixed, RenderStateModel& moving);
  ~RenderLink();
  RenderLink(const RenderLink&) = delete;
  RenderLink& operator=(const RenderLink&) = delete;
  bool lookLinked() const { return lookLinked_; }
  void setLookLinked(bool on);  // on: the moving column takes the fixed one's look now
  // The moving column's camera (and look, if linked) follows the fixed one now.
  void syncMovingToFixed();

 private:
  void follow(RenderStateModel& leader, RenderStateModel& follower, bool fixedLeads, unsigned what);
  ComparisonModel& model_;
  RenderStateModel &fixed_, &moving_;
  bool lookLinked_ = true, busy_ = false;
  int fixedConn_ = 0, movingConn_ = 0, modelConn_ = 0;
};

}  // namespace voxray
