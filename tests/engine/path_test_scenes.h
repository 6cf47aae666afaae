#pragma once
// Scenes with known answers for the path tracer's tests, and a one-call kernel render.
#include <cstdint>

#include "voxray/engine/path_tracer.h"
#include "voxray/io/volume.h"

namespace voxray::test {

struct PathImage {
  Image image;
  FloatImage radiance;
};

// spp paths per pixel in one launch on PoCL, from a fresh raycaster and path tracer.
PathImage pathRender(const Volume& v, const RenderParams& p, int spp, uint32_t seed = 1);

// 8 x 8 x 8 voxels of 1 mm at 0 HU.
Volume slabVolume();
// Orthographic from anterior, 32 x 24, a constant table (colour albedo, opacity alpha per
// mm) and a white background behind the slab.
RenderParams slabParams(double alpha, glm::dvec3 albedo);

// 16^3 voxels of 1 mm: a scattering block (500 HU) in slices z 0 ... 9, air in 10 and 11,
// and a black slab (1000 HU) in 12 ... 15 (superior).
Volume shadowVolume();
// Orthographic from anterior, 32 x 24; the light at 1e30 mm superior with this `diffuse`,
// ambient 0.3; the table's entries 4 and 5 (the slab) have opacity 1.
RenderParams shadowParams(double diffuse);

// test::ball 16^3 (radius 5 voxels) with a soft two-colour table, 16 x 12, perspective.
Volume ballVolume();
RenderParams ballParams();

}  // namespace voxray::test
