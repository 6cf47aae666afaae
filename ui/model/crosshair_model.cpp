#include "crosshair_model.h"

#include <cmath>

namespace voxray::ui {

void CrosshairModel::setDims(const glm::ivec3& dims) {
  dims_ = glm::max(dims, glm::ivec3(1));
  voxel_ = glm::ivec3(-1);  // forces a notification below
  setVoxel(dims_ / 2);
}

void CrosshairModel::setVoxel(const glm::ivec3& voxel) {
  glm::ivec3 clamped = glm::clamp(voxel, glm::ivec3(0), dims_ - 1);
  if (clamped == voxel_) return;
  voxel_ = clamped;
  changed.notify();
}

void CrosshairModel::clickInView(const SliceAxes& axes, double u, double v) {
  glm::dvec3 p = sliceToVoxel(axes, dims_, u, v, voxel_[axes.nAxis]);
  setVoxel(glm::ivec3(glm::round(p)));
}

void CrosshairModel::scrollView(const SliceAxes& axes, int steps) {
  glm::ivec3 next = voxel_;
  next[axes.nAxis] += steps;
  setVoxel(next);
}

}  // namespace voxray::ui
