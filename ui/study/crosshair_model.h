#pragma once
// The linked crosshair: one position shared by the three slice views. Each view shows the
// plane through it across its own normal, so clicking in one view moves the other two, and
// scrolling a view moves the crosshair along that view's normal.
//
// Oblique MPR (as in 3D Slicer and Horos): turning the crosshair's axes in one view turns
// the other two views' planes about that view's normal, so the three stay orthogonal and
// linked; the view turned in keeps its own plane. Each view also has a slab (plane_sampler.h).
// While nothing is turned the crosshair sits on voxel centres and the views show the
// acquisition slices (slicePlane); once turned it moves continuously.
#include <array>

#include <glm/glm.hpp>

#include "mpr_planes.h"
#include "notifier.h"
#include "slice_geometry.h"
#include "voxray/engine/plane_sampler.h"

namespace voxray {

class CrosshairModel {
 public:
  // Resets to the volume's centre and the acquisition planes for new dimensions, with 1 mm
  // voxels along the LPS axes (setGeometry gives the volume's own).
  void setDims(const glm::ivec3& dims);
  void setGeometry(const glm::ivec3& dims, const glm::dvec3& spacingMm,
                   const glm::dmat3& direction);
  const glm::ivec3& dims() const { return dims_; }
  const glm::dvec3& spacingMm() const { return spacing_; }
  const glm::dmat3& direction() const { return direction_; }
  glm::ivec3 voxel() const { return glm::ivec3(glm::round(centre_)); }  // nearest voxel
  const glm::dvec3& centre() const { return centre_; }  // voxel coordinates, continuous
  void setVoxel(const glm::ivec3& voxel);               // clamped into the volume

  // The voxel position (continuous) at slice coordinates (u, v) of a view, on the plane it
  // shows (turned about the crosshair when oblique).
  glm::dvec3 viewToVoxel(const SliceAxes& axes, double u, double v) const;
  // A click at slice coordinates (u, v) of a view: moves within that view's plane.
  void clickInView(const SliceAxes& axes, double u, double v);
  // Wheel or arrow keys in a view: moves along that view's normal by STEPS slices.
  void scrollView(const SliceAxes& axes, int steps);
  int sliceOf(const SliceAxes& axes) const { return voxel()[axes.nAxis]; }

  // The view's rotation about the crosshair (LPS); the identity for an acquisition plane.
  const glm::dmat3& rotation(Orientation o) const { return rotation_[size_t(o)]; }
  bool rotated() const;
  PlaneFrame frame(const SliceAxes& axes) const;  // the view's plane as it is shown
  // Turns the crosshair's axes in the view by ANGLERAD, clockwise on screen (y down): the
  // other two planes turn about this view's normal.
  void rotateInView(const SliceAxes& axes, double angleRad);
  // Back to the acquisition planes, the crosshair on the nearest voxel centre.
  void resetRotation();
  // The three views' rotations and the crosshair at once (an opened session): one change.
  void setPlanes(const glm::dvec3& centre, const std::array<glm::dmat3, 3>& rotations);

  const Slab& slab(Orientation o) const { return slab_[size_t(o)]; }
  void setSlab(Orientation o, const Slab& slab);

  Notifier<> changed;

 private:
  void moveTo(const glm::dvec3& centre);  // clamped; rounded while nothing is turned
  glm::dmat3 voxelToMm() const;

  glm::ivec3 dims_{1};
  glm::dvec3 spacing_{1.0};
  glm::dmat3 direction_{1.0};
  glm::dvec3 centre_{0.0};
  std::array<glm::dmat3, 3> rotation_{glm::dmat3(1.0), glm::dmat3(1.0), glm::dmat3(1.0)};
  std::array<Slab, 3> slab_{};
};

}  // namespace voxray
