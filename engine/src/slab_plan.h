#pragma once
// How a volume too large for one device allocation or 3D image is split along z into slabs
// ("bricks"). Slab s owns slices [s * depth, min((s + 1) * depth, dimZ)) and stores kApron
// more on each side (clamped to the volume), so every stencil a kernel reads around a point
// whose floor(z) the slab owns (trilinear, nearest, the gradients' 4x4x4 block from floor - 1
// to floor + 2) lies in that one slab: kernels/reconstruction/slabs.cl picks it per sample.
#include <cstddef>
#include <optional>
#include <vector>

namespace voxray {

struct SlabPlan {
  static constexpr int kApron = 2;     // kernels/reconstruction/slabs.cl: SLAB_APRON
  static constexpr int kMaxSlabs = 8;  // kernel arguments vol0 .. vol7
  struct Slab {
    int first = 0;   // first stored slice (apron included)
    int stored = 0;  // stored slices (apron included)
  };
  int depth = 0;  // slices each slab owns; the last may own fewer
  std::vector<Slab> slabs;

  int count() const { return int(slabs.size()); }
};

// The slabs of `depth` owned slices each (depth >= 1) for a volume of dimZ slices.
SlabPlan slabsOfDepth(int dimZ, int depth);

// The fewest slabs (one when the volume fits) that each store at most maxStoredSlices
// slices, or nothing when kMaxSlabs do not suffice.
std::optional<SlabPlan> planSlabs(int dimZ, size_t maxStoredSlices);

}  // namespace voxray
