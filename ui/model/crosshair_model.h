#pragma once
// The linked crosshair: one voxel position shared by the three slice views. Each view
// shows the slice through it across its own normal, so clicking in one view moves the
// other two, and scrolling a view moves the crosshair along that view's normal.
#include <glm/glm.hpp>

#include "notifier.h"
#include "slice_geometry.h"

namespace voxray::ui {

class CrosshairModel {
 public:
  // Resets to the volume's centre for new dimensions.
  void setDims(const glm::ivec3& dims);
  const glm::ivec3& dims() const { return dims_; }
  const glm::ivec3& voxel() const { return voxel_; }
  void setVoxel(const glm::ivec3& voxel);  // clamped into the volume

  // A click at slice coordinates (u, v) of a view: moves the two in-plane axes.
  void clickInView(const SliceAxes& axes, double u, double v);
  // Wheel or arrow keys in a view: moves along that view's normal by STEPS slices.
  void scrollView(const SliceAxes& axes, int steps);
  int sliceOf(const SliceAxes& axes) const { return voxel_[axes.nAxis]; }

  Notifier<> changed;

 private:
  glm::ivec3 dims_{1};
  glm::ivec3 voxel_{0};
};

}  // namespace voxray::ui
