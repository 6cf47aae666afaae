#pragma once
// A slice of the volume as a grey image with window/level applied, in screen order
// (see slice_geometry.h), resampled by the engine (plane_sampler.h) onto square pixels of
// the smaller in-plane spacing, so that the image has the slice's physical aspect.
#include <string>

#include "no_qt.h"
#include "slice_geometry.h"
#include "voxray/engine/plane_sampler.h"
#include "voxray/io/image.h"
#include "window_level.h"

namespace voxray {
struct Volume;
}

namespace voxray {

// The plane a view shows at SLICE: pixels over the whole slice, screen x along axes.uAxis
// and y along axes.vAxis (flips applied), at most kMaxSlicePixels on a side. A fractional
// SLICE lies between two slices (an oblique view's crosshair between voxel centres).
constexpr int kMaxSlicePixels = 4096;
PlaneGrid slicePlane(const Volume& v, const SliceAxes& axes, double slice);

// The plane a view shows through the crosshair at CENTREVOXEL: slicePlane through it, turned
// by ROTATION (LPS) about it; slicePlane itself for the identity. Same size and pixel
// spacing, so slice coordinates, zoom and the scale bar mean the same on an oblique plane.
PlaneGrid viewPlane(const Volume& v, const SliceAxes& axes, const glm::dvec3& centreVoxel,
                    const glm::dmat3& rotation);

// The slice's image (slicePlane's size); an empty image for an empty volume.
Image renderSlice(const Volume& v, const SliceAxes& axes, int slice, const WindowLevel& wl,
                  Interp interp);
// Any plane's image, thin or a slab; what lies outside the volume is black.
Image renderPlane(const Volume& v, const PlaneGrid& g, const WindowLevel& wl, Interp interp,
                  const Slab& slab = {});

// Physical value at a voxel (nearest), or NaN outside the volume.
double sampleValue(const Volume& v, const glm::dvec3& voxel);

// The HU probe: what the cursor at VOXEL (continuous) reads in a view that samples with
// INTERP, exactly as the slice image is resampled (samplePlane). Nearest reads and places
// the nearest voxel; Linear reads the trilinear value at the cursor itself.
struct CursorProbe {
  bool inside = false;        // false: outside the volume, no value
  double value = 0.0;         // physical units (Volume::unit), or SUVbw (readoutValue)
  glm::ivec3 voxel{0};        // nearest voxel index
  glm::dvec3 patientMm{0.0};  // LPS position of the reading
  std::string unit;
  int decimals = 0;  // how the readout prints VALUE
};
CursorProbe probeAt(const Volume& v, const glm::dvec3& voxel, Interp interp);

}  // namespace voxray
