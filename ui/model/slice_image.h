#pragma once
// A slice of the volume as a grey image with window/level applied, in screen order
// (see slice_geometry.h). One image pixel per voxel; the view scales by the spacing.
#include "no_qt.h"
#include "slice_geometry.h"
#include "voxray/io/image.h"
#include "window_level.h"

namespace voxray {
struct Volume;
}

namespace voxray::ui {

// Width = dims[uAxis], height = dims[vAxis]. An empty image for an empty volume.
Image renderSlice(const Volume& v, const SliceAxes& axes, int slice, const WindowLevel& wl);

// Physical value at a voxel (nearest), or NaN outside the volume.
double sampleValue(const Volume& v, const glm::dvec3& voxel);

}  // namespace voxray::ui
