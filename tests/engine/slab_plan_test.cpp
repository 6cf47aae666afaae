// The z slabs a volume too large for one allocation is split into (engine/src/slab_plan.h):
// first stored slice, stored depth and apron in edge cases, and the claim the kernels rely
// on: every stencil around a point lies in the slab owning floor(z).
#include <gtest/gtest.h>

#include <algorithm>

#include "slab_plan.h"

namespace voxray {

namespace {

std::vector<std::pair<int, int>> slabs(const SlabPlan& p) {
  std::vector<std::pair<int, int>> out;
  for (const SlabPlan::Slab& s : p.slabs) out.emplace_back(s.first, s.stored);
  return out;
}

using SlabList = std::vector<std::pair<int, int>>;  // (first stored slice, stored slices)

}  // namespace

TEST(SlabPlan, AVolumeThatFitsIsOneSlabWithoutApron) {
  auto p = planSlabs(113, 113);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->depth, 113);
  EXPECT_EQ(slabs(*p), (SlabList{{0, 113}}));
  EXPECT_EQ(slabs(*planSlabs(1, 1)), (SlabList{{0, 1}}));
}

TEST(SlabPlan, DepthNotDividingTheVolumeLeavesAShorterLastSlab) {
  // Owned [0, 4), [4, 8), [8, 10); two apron slices each side, clamped to [0, 10).
  SlabPlan p = slabsOfDepth(10, 4);
  EXPECT_EQ(p.depth, 4);
  EXPECT_EQ(slabs(p), (SlabList{{0, 6}, {2, 8}, {6, 4}}));
}

TEST(SlabPlan, DepthSmallerThanTheApronOverlapsSeveralSlabs) {
  EXPECT_EQ(slabs(slabsOfDepth(5, 1)), (SlabList{{0, 3}, {0, 4}, {0, 5}, {1, 4}, {2, 3}}));
}

TEST(SlabPlan, TheFewestSlabsWithinTheLimit) {
  // Two slabs of 50 store 52 slices each (one apron side); at 51 it takes three of 34.
  EXPECT_EQ(slabs(*planSlabs(100, 60)), (SlabList{{0, 52}, {48, 52}}));
  auto three = planSlabs(100, 51);
  ASSERT_TRUE(three);
  EXPECT_EQ(three->depth, 34);
  EXPECT_EQ(slabs(*three), (SlabList{{0, 36}, {32, 38}, {66, 34}}));
}

TEST(SlabPlan, NoPlanWhenEightSlabsDoNotFit) {
  EXPECT_FALSE(planSlabs(100, 10));  // 8 slabs of 13 store 17 slices in the middle
  EXPECT_FALSE(planSlabs(100, 4));   // no depth leaves room for two aprons
  EXPECT_FALSE(planSlabs(100, 0));
  EXPECT_TRUE(planSlabs(100, 17));
}

// kernels/reconstruction/slabs.cl: a point with floor(z) = f reads slices f - 1 .. f + 2 (the
// gradients' 4x4x4 block; trilinear and nearest read fewer), clamped to the volume, from the slab
// owning f (the nearest end slab outside the volume). Clamped to that slab's stored range
// instead, they must be the same slices.
TEST(SlabPlan, EveryStencilLiesInTheSlabOwningItsFloor) {
  for (int dimZ = 1; dimZ <= 40; ++dimZ)
    for (int depth = 1; depth <= dimZ; ++depth) {
      SlabPlan p = slabsOfDepth(dimZ, depth);
      ASSERT_LE(p.count(), dimZ);
      for (int f = -3; f <= dimZ + 3; ++f) {
        int s = std::clamp(f < 0 ? 0 : f / depth, 0, p.count() - 1);
        const SlabPlan::Slab& slab = p.slabs[size_t(s)];
        for (int z = f - 1; z <= f + 2; ++z) {
          int inVolume = std::clamp(z, 0, dimZ - 1);
          int inSlab = std::clamp(z, slab.first, slab.first + slab.stored - 1);
          ASSERT_EQ(inVolume, inSlab) << "dimZ " << dimZ << " depth " << depth << " floor " << f;
        }
      }
    }
}

}  // namespace voxray
