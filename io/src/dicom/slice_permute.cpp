#include "slice_permute.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace voxray::dicom {
namespace {

// voxel_memory.cpp maps blocks of this size and more on their own (page-aligned, nothing
// else in their pages); smaller ones come from the heap and are copied.
constexpr size_t kMappedBlock = size_t(2) << 20;
// Below this many pages a slice is copied: each move is a system call and a mapping.
constexpr size_t kMinPages = 16;

// Follows SOURCE's cycles: MOVE(from, to) for each slice, with one slice aside per cycle
// (ASIDE() gives its address, once per cycle).
template <class Move, class Aside>
void followCycles(int16_t* base, size_t sliceSize, const std::vector<size_t>& source, Move move,
                  Aside asideSlice) {
  std::vector<bool> placed(source.size(), false);
  auto slice = [&](size_t k) { return base + k * sliceSize; };
  for (size_t start = 0; start < source.size(); ++start) {
    if (placed[start] || source[start] == start) continue;
    int16_t* aside = asideSlice();
    move(slice(start), aside);
    size_t k = start;
    while (source[k] != start) {
      move(slice(source[k]), slice(k));
      placed[k] = true;
      k = source[k];
    }
    move(aside, slice(k));
    placed[k] = true;
  }
}

void copySlices(VoxelVector& voxels, size_t sliceSize, const std::vector<size_t>& source) {
  std::vector<int16_t> aside(sliceSize);
  followCycles(
      voxels.data(), sliceSize, source,
      [&](const int16_t* from, int16_t* to) { std::copy_n(from, sliceSize, to); },
      [&] { return aside.data(); });
}

#if defined(__linux__)

size_t pageSize() { return size_t(sysconf(_SC_PAGESIZE)); }

// The pages at FROM (BYTES) become those at TO, whose own pages (already moved on, or the
// aside's reservation) are given up. Where the kernel refuses (the mapping count limit),
// TO gets fresh pages and a copy.
void movePages(int16_t* from, int16_t* to, size_t bytes) {
  if (mremap(from, bytes, bytes, MREMAP_MAYMOVE | MREMAP_FIXED, to) != MAP_FAILED) return;
  if (mmap(to, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0) ==
      MAP_FAILED)
    throw std::bad_alloc();
  std::memcpy(to, from, bytes);
}

void moveSlicePages(VoxelVector& voxels, size_t sliceSize, const std::vector<size_t>& source) {
  const size_t bytes = sliceSize * sizeof(int16_t);
  followCycles(
      voxels.data(), sliceSize, source,
      [&](int16_t* from, int16_t* to) { movePages(from, to, bytes); },
      // Address space for the aside, no memory: the first move of the cycle replaces it,
      // the last one takes it away.
      [&] {
        void* p =
            mmap(nullptr, bytes, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        if (p == MAP_FAILED) throw std::bad_alloc();
        return static_cast<int16_t*>(p);
      });
}

#endif

}  // namespace

bool slicesMoveAsPages(const VoxelVector& voxels, size_t sliceSize) {
#if defined(__linux__)
  const size_t page = pageSize(), bytes = sliceSize * sizeof(int16_t);
  return bytes % page == 0 && bytes >= kMinPages * page &&
         voxels.capacity() * sizeof(int16_t) >= kMappedBlock &&
         reinterpret_cast<uintptr_t>(voxels.data()) % page == 0;
#else
  (void)voxels;
  (void)sliceSize;
  return false;
#endif
}

void permuteSlices(VoxelVector& voxels, size_t sliceSize, const std::vector<size_t>& source) {
#if defined(__linux__)
  if (slicesMoveAsPages(voxels, sliceSize)) {
    moveSlicePages(voxels, sliceSize, source);
    return;
  }
#endif
  copySlices(voxels, sliceSize, source);
}

}  // namespace voxray::dicom
