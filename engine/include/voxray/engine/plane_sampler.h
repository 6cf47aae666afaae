#pragma once
// A plane of the volume resampled into a 2D grid of physical values: the slice views' image
// (the three orthogonal planes) and any oblique plane, thin or as a slab (MIP, MinIP, mean).
// CPU only: one plane is small work (docs of the cost: README "Slices: oblique and slabs").
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/render_params.h"

namespace voxray {

struct Volume;

// A grid of sample points in patient LPS (mm). Pixel (x, y) is sampled at
// originMm + x * spacingMm.x * uDir + y * spacingMm.y * vDir.
struct PlaneGrid {
  glm::dvec3 originMm{0.0};                             // centre of pixel (0, 0)
  glm::dvec3 uDir{1.0, 0.0, 0.0}, vDir{0.0, 1.0, 0.0};  // unit vectors along x and y
  glm::dvec2 spacingMm{1.0};                            // pixel spacing along x and y
  glm::ivec2 size{0};                                   // pixels along x and y
};

// Physical values (stored * slope + intercept), row by row (x fastest). A point inside the
// volume's box (voxel cells, [-0.5, n - 0.5] per axis) takes the voxel (Nearest) or the
// trilinear blend of its eight neighbours, edge voxels repeated past the outer centres
// (Linear; the reconstruction the raycaster uses); a point outside takes BACKGROUND.
std::vector<float> samplePlane(const Volume& v, const PlaneGrid& g, Interp interp,
                               float background);

// A slab across the plane: THICKNESSMM centred on it (0: the thin plane), its samples along
// the normal uDir x vDir reduced to the brightest (Mip), darkest (MinIp) or their mean.
enum class SlabMode { Mip, MinIp, Mean };
struct Slab {
  double thicknessMm = 0.0;
  SlabMode mode = SlabMode::Mip;
};
const char* toString(SlabMode m);              // "mip", "minip", "mean"
SlabMode parseSlabMode(const std::string& s);  // throws Error (Input) naming the choices

// Samples per pixel of SLAB: 1 for a thin plane, else one every smallest voxel spacing or
// closer, the first and last on the slab's faces.
int slabSamples(const Volume& v, const Slab& slab);

// samplePlane reduced over the slab: a thickness of 0 (or less) is samplePlane itself. Only
// samples inside the volume's box count; a pixel with none takes BACKGROUND.
std::vector<float> samplePlane(const Volume& v, const PlaneGrid& g, Interp interp, float background,
                               const Slab& slab);

}  // namespace voxray
