// The empty-space grid's leap distances (engine/src/leap_distances.h: three passes on the
// device, linear sweeps or per cell) equal the chessboard distance to the nearest occupied cell,
// capped at 15, found by brute force; and the dvr occupancy folded per stored value
// (engine/src/dvr_occupancy.h) is the test it replaces, entry by entry. White box: the passes run
// on the test device's queue.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

#include "cl_context_impl.h"
#include "dvr_occupancy.h"
#include "leap_distances.h"
#include "stability_helpers.h"

namespace voxray {

namespace {

// Per cell, min over occupied cells of the largest axis distance, capped: the definition.
std::vector<uint8_t> bruteForce(const std::vector<uint8_t>& occ, glm::ivec3 n) {
  std::vector<glm::ivec3> occupied;
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x)
        if (occ[(size_t(z) * n.y + y) * n.x + x]) occupied.push_back({x, y, z});
  std::vector<uint8_t> d(occ.size(), kMaxLeap);
  for (int z = 0; z < n.z; ++z)
    for (int y = 0; y < n.y; ++y)
      for (int x = 0; x < n.x; ++x) {
        int best = kMaxLeap;
        for (const glm::ivec3& o : occupied)
          best =
              std::min(best, std::max({std::abs(o.x - x), std::abs(o.y - y), std::abs(o.z - z)}));
        d[(size_t(z) * n.y + y) * n.x + x] = uint8_t(best);
      }
  return d;
}

std::vector<uint8_t> onDevice(const std::vector<uint8_t>& occ, glm::ivec3 n, LeapPasses how) {
  ContextImpl& cl = test::pocl().impl();
  std::vector<uint8_t> out(occ.size(), 0xEE);
  cl::Buffer in(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, occ.size(),
                const_cast<uint8_t*>(occ.data()));
  cl::Buffer leap(cl.context, CL_MEM_READ_WRITE, occ.size());
  cl::Buffer scratch(cl.context, CL_MEM_READ_WRITE, occ.size());
  enqueueLeapDistances(cl, in, leap, scratch, n, how);
  cl.queue.enqueueReadBuffer(leap, CL_TRUE, 0, out.size(), out.data());
  return out;
}

}  // namespace

// Grids whose x side is and is not a multiple of the 16 lanes of the y and z passes, flat and
// long ones (anisotropic cells make such grids: 512x512x100 voxels, 2000x12x12), single cells
// and lines; empty, one occupied cell (distances up to the cap) and random densities. Integers:
// every cell must match exactly.
TEST(LeapDistances, EqualTheBruteForceChessboardDistance) {
  const glm::ivec3 sizes[] = {{1, 1, 1},    {16, 1, 1},  {1, 1, 40}, {1, 37, 1},   {17, 9, 5},
                              {35, 20, 12}, {64, 4, 40}, {5, 70, 6}, {33, 33, 33}, {48, 2, 2}};
  std::mt19937 rng(35);
  for (const glm::ivec3& n : sizes) {
    const size_t cells = size_t(n.x) * n.y * n.z;
    for (double density : {0.0, -1.0, 0.002, 0.03, 0.3}) {
      SCOPED_TRACE(testing::Message() << n.x << "x" << n.y << "x" << n.z << ", density " << density
                                      << " (-1: one cell)");
      std::vector<uint8_t> occ(cells, 0);
      if (density < 0) {
        occ[cells / 3] = 1;
      } else {
        std::bernoulli_distribution coin(density);
        // Occupancy other than 1 counts too (the kernels test nonzero).
        for (auto& o : occ) o = coin(rng) ? uint8_t(1 + rng() % 3) : 0;
      }
      const std::vector<uint8_t> want = bruteForce(occ, n);
      // Both ways the device may run the passes (CPUs sweep, GPUs go per cell).
      for (LeapPasses how : {LeapPasses::Sweeps, LeapPasses::PerCell}) {
        SCOPED_TRACE(how == LeapPasses::Sweeps ? "sweeps" : "per cell");
        const std::vector<uint8_t> got = onDevice(occ, n, how);
        size_t wrong = 0, first = cells;
        for (size_t c = 0; c < cells; ++c)
          if (got[c] != want[c] && wrong++ == 0) first = c;
        EXPECT_EQ(wrong, 0u) << "first at cell " << first << ": got " << int(got[first])
                             << ", want " << int(want[first]);
        // The cap is reached where nothing is near: the empty grid is 15 everywhere.
        if (density == 0.0) {
          EXPECT_EQ(*std::min_element(got.begin(), got.end()), kMaxLeap);
        }
      }
    }
  }
}

// The single occupied cell in a long line: its distances count up one per cell to the cap.
TEST(LeapDistances, CountUpFromAnOccupiedCellToTheCap) {
  const glm::ivec3 n{3, 40, 2};
  std::vector<uint8_t> occ(size_t(n.x) * n.y * n.z, 0);
  occ[(size_t(1) * n.y + 10) * n.x + 2] = 1;  // (2, 10, 1)
  for (LeapPasses how : {LeapPasses::Sweeps, LeapPasses::PerCell}) {
    const std::vector<uint8_t> d = onDevice(occ, n, how);
    for (int y = 0; y < n.y; ++y)
      EXPECT_EQ(int(d[size_t(y) * n.x]), std::min(std::max(std::abs(y - 10), 2), 15))
          << y << (how == LeapPasses::Sweeps ? " (sweeps)" : " (per cell)");
  }
}

// classify.cl's dvr test, written out: the entries a cell with min a and max b can read, with
// half a stored unit and one entry of margin, include a non-transparent one.
TEST(DvrCellBounds, FoldTheEntryTestPerStoredValue) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    const int entries = 2 + int(rng() % 300);
    std::vector<float> alpha(size_t(entries), 0.0f);
    std::bernoulli_distribution coin(trial % 4 == 0 ? 0.5 : 0.03);
    for (float& a : alpha) a = coin(rng) ? 0.5f : 0.0f;
    std::vector<int> before(size_t(entries) + 1, 0);
    for (int e = 0; e < entries; ++e) before[e + 1] = before[e] + (alpha[e] > 0.0f);
    const float storedMin = -200.0f + float(rng() % 400),
                scale = 0.05f + float(rng() % 100) / 37.0f;
    const int lo = -300 + int(rng() % 100), hi = lo + int(rng() % 600);
    const DvrCellBounds b = dvrCellBounds(before, storedMin, scale, lo, hi);
    ASSERT_EQ(b.from.size(), size_t(hi - lo + 1));
    const int last = entries - 1;
    for (int n = 0; n < 2000; ++n) {
      int a = lo + int(rng() % (hi - lo + 1)), c = lo + int(rng() % (hi - lo + 1));
      if (a > c) std::swap(a, c);
      float x0 = std::clamp((float(a) - 0.5f - storedMin) * scale, 0.0f, float(last));
      float x1 = std::clamp((float(c) + 0.5f - storedMin) * scale, 0.0f, float(last));
      int e0 = std::max(int(std::floor(x0)) - 1, 0), e1 = std::min(int(std::floor(x1)) + 2, last);
      bool shows = false;
      for (int e = e0; e <= e1; ++e) shows = shows || alpha[e] > 0.0f;
      ASSERT_EQ(b.to[c - lo] > b.from[a - lo], shows)
          << "trial " << trial << ", cell values " << a << " ... " << c;
    }
  }
}

}  // namespace voxray
