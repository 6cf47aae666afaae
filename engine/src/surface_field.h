#pragma once
// The smoothed occupancy field of a segment shown as a surface (issue 34, the raycaster's
// surface pass, kernels/surface/surface_layer.cl): the segment's binary mask filtered by a
// Gaussian into 8-bit values (255 inside, 0 outside), over the segment's voxel box padded by
// the filter's reach, so that the field's 0.5 level is a smooth surface with normals from
// its gradient instead of the label map's voxel stairs.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/io/segmentation.h"

namespace voxray {

struct SurfaceField {
  uint8_t label = 0;
  glm::ivec3 lo{0};             // the field's voxel (0,0,0) in the label map
  glm::ivec3 dims{0};           // 0: the segment has no voxel
  std::vector<uint8_t> values;  // dims' voxels, x fastest
  // Per SURFACE_BLOCK^3 voxels (kernels/surface_layer.h) 1 where the 0.5 level may lie.
  glm::ivec3 blockDims{0};
  std::vector<uint8_t> blocks;
  // What it was built from: the segment's voxel box then (the field's box less its padding)
  // and the sigma.
  glm::ivec3 coreLo{0}, coreHi{-1};
  float sigma = 0.0f;
  bool empty() const { return values.empty(); }
};

// The Gaussian's sigma in voxels along each axis: in voxels, so that it smooths the stairs of
// each axis's own spacing (a 3 mm slice step and a 0.5 mm row step alike). It moves a curved
// surface's 0.5 level inward by about sigma^2 / radius (0.1 voxel on a 15-voxel sphere) and
// lowers a plate w voxels thick to a peak of erf(w / (2 sqrt(2) sigma)): at 1.25 a 2-voxel plate
// (thin skull) keeps 0.58 and shows, a 1-voxel one (0.31) does not. On a 15-voxel sphere the
// normals' error was 2.4 / 7.2 deg (median / 95th) at sigma 1, 1.6 / 4.6 at 1.25, 1.05 / 3.3 at
// 1.5 (where 2-voxel plates vanish): tests/engine/surfaces_test.cpp.
constexpr float kSurfaceSigmaVoxels = 1.25f;

// SEG's segment LABEL as a field. SIGMA 0: the mask itself (the blocky label surface the tests
// compare with). Runs on parallelFor's threads (the caller is the render thread, never the GUI).
SurfaceField buildSurfaceField(const Segmentation& seg, uint8_t label,
                               float sigmaVoxels = kSurfaceSigmaVoxels);

// After an edit of the label map in the box LO ... HI (inclusive): FIELD's values again over the
// box and the filter's reach around it, equal to a new build's there, when the segment's voxels
// in the box lie inside the box FIELD was built over (a paint dab on a large segment costs its
// own neighbourhood, not the segment). False, FIELD unchanged, when they do not (the segment
// grew out of its box: build it again).
bool updateSurfaceField(SurfaceField& field, const Segmentation& seg, glm::ivec3 lo, glm::ivec3 hi);

// Whether an edit of the label map in the box LO ... HI (inclusive) may change FIELD: the box
// meets its padded box, or holds its label now (the segment grew outside it).
bool surfaceFieldTouched(const SurfaceField& field, const Segmentation& seg, glm::ivec3 lo,
                         glm::ivec3 hi);

}  // namespace voxray
