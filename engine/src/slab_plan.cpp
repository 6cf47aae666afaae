#include "slab_plan.h"

#include <algorithm>

namespace voxray {

SlabPlan slabsOfDepth(int dimZ, int depth) {
  SlabPlan plan;
  plan.depth = depth;
  for (int owned = 0; owned < dimZ; owned += depth) {
    int first = std::max(owned - SlabPlan::kApron, 0);
    int end = std::min(owned + depth + SlabPlan::kApron, dimZ);
    plan.slabs.push_back({first, end - first});
  }
  return plan;
}

std::optional<SlabPlan> planSlabs(int dimZ, size_t maxStoredSlices) {
  if (size_t(dimZ) <= maxStoredSlices) return slabsOfDepth(dimZ, dimZ);
  for (int k = 2; k <= SlabPlan::kMaxSlabs; ++k) {
    SlabPlan plan = slabsOfDepth(dimZ, (dimZ + k - 1) / k);
    bool fits = std::all_of(plan.slabs.begin(), plan.slabs.end(), [&](const SlabPlan::Slab& s) {
      return size_t(s.stored) <= maxStoredSlices;
    });
    if (fits) return plan;
  }
  return std::nullopt;
}

}  // namespace voxray
