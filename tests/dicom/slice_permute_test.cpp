// permuteSlices (slice_permute.h): slices decoded in arrival order end up in stack order,
// every voxel, whether their pages are moved (whole-page slices of a mapped block: the
// 512x512 CT slices of a PACS retrieval) or their bytes copied. Exact: values are moved,
// never computed.
#include <algorithm>
#include <cstdint>
#include <fstream>
#include <numeric>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "slice_permute.h"

namespace voxray::dicom {
namespace {

// Voxel i of slice k holds a value of both (distinct across slices and within one).
int16_t mark(size_t k, size_t i) { return int16_t((k * 7919 + i * 31) & 0x7fff); }

VoxelVector markedSlices(size_t count, size_t sliceSize) {
  VoxelVector v;
  v.resize(count * sliceSize);
  for (size_t k = 0; k < count; ++k)
    for (size_t i = 0; i < sliceSize; ++i) v[k * sliceSize + i] = mark(k, i);
  return v;
}

// The number of voxels not where SOURCE says they go (0 when all moved right).
size_t misplaced(const VoxelVector& v, size_t sliceSize, const std::vector<size_t>& source) {
  size_t wrong = 0;
  for (size_t k = 0; k < source.size(); ++k)
    for (size_t i = 0; i < sliceSize; ++i) wrong += v[k * sliceSize + i] != mark(source[k], i);
  return wrong;
}

// How many mappings of this process start inside V's memory (/proc/self/maps): each moved
// slice starts one (unless the kernel merges it with a neighbour).
size_t mappingsIn(const VoxelVector& v) {
  const auto from = reinterpret_cast<uintptr_t>(v.data()), to = from + v.size() * sizeof(int16_t);
  std::ifstream maps("/proc/self/maps");
  size_t n = 0;
  for (std::string line; std::getline(maps, line);) {
    uintptr_t start = 0;
    std::istringstream(line) >> std::hex >> start;
    n += start >= from && start < to;
  }
  return n;
}

std::vector<std::vector<size_t>> orders(size_t n) {
  std::vector<size_t> identity(n), reversed(n), shuffled(n), rotated(n);
  std::iota(identity.begin(), identity.end(), size_t(0));
  reversed.assign(identity.rbegin(), identity.rend());
  shuffled = identity;
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(39));
  std::rotate_copy(identity.begin(), identity.begin() + 3, identity.end(), rotated.begin());
  return {identity, reversed, shuffled, rotated};  // rotated: one cycle through every slice
}

TEST(SlicePermute, WholePageSlicesOfAMappedBlockMoveAsPagesToTheirPlace) {
  const size_t sliceSize = 512 * 512, count = 40;  // 20 MiB: a block of its own
  for (const auto& source : orders(count)) {
    VoxelVector v = markedSlices(count, sliceSize);
    ASSERT_TRUE(slicesMoveAsPages(v, sliceSize));
    const size_t mappings = mappingsIn(v);
    permuteSlices(v, sliceSize, source);
    EXPECT_EQ(misplaced(v, sliceSize, source), 0u);
    // Pages moved, not bytes copied in place: a moved slice is a mapping of its own.
    if (source.front() != 0) EXPECT_GT(mappingsIn(v), mappings);
    // Every page is there and writable after the moves (a hole would fault here), and the
    // block is released whole when the vector goes.
    std::fill(v.begin(), v.end(), int16_t(-1000));
    EXPECT_EQ(std::count(v.begin(), v.end(), int16_t(-1000)), std::ptrdiff_t(v.size()));
  }
}

TEST(SlicePermute, SlicesOfPartPagesOrASmallBlockAreCopiedToTheirPlace) {
  // 8x8 slices (the PET phantom's) and 100x100 (200 bytes short of 5 pages).
  for (size_t sliceSize : {size_t(64), size_t(100 * 100)}) {
    const size_t count = 300;
    for (const auto& source : orders(count)) {
      VoxelVector v = markedSlices(count, sliceSize);
      ASSERT_FALSE(slicesMoveAsPages(v, sliceSize));
      permuteSlices(v, sliceSize, source);
      EXPECT_EQ(misplaced(v, sliceSize, source), 0u) << sliceSize;
    }
  }
}

}  // namespace
}  // namespace voxray::dicom
