#pragma once
// Memory for a volume's voxels. The raycaster's gathers on a CPU device read the voxels
// where they are (no device copy), scattered over the whole volume: with 4 KiB pages a
// real-size CT (200 MB) is 50,000 pages and most gathers miss the TLB. On Linux, blocks of
// 2 MiB or more are therefore 2 MiB-aligned and marked for transparent huge pages before
// their first write (THP is `madvise` on most distributions: only marked memory gets them).
// Elsewhere, and for smaller blocks, it is a plain allocation.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace voxray {

// BYTES of zeroed memory, and its release; never null (throws std::bad_alloc).
void* allocateVoxelMemory(size_t bytes);
void releaseVoxelMemory(void* p, size_t bytes) noexcept;

template <class T>
struct VoxelAllocator {
  using value_type = T;
  VoxelAllocator() = default;
  template <class U>
  VoxelAllocator(const VoxelAllocator<U>&) noexcept {}
  T* allocate(size_t n) { return static_cast<T*>(allocateVoxelMemory(n * sizeof(T))); }
  void deallocate(T* p, size_t n) noexcept { releaseVoxelMemory(p, n * sizeof(T)); }
  // Elements made without a value are left as the memory holds them, zero: a vector sized
  // for a volume is not filled on one thread first (the importers write every voxel, and
  // the pages then fault on the threads that write them).
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... A>
  void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
  template <class U>
  bool operator==(const VoxelAllocator<U>&) const noexcept {
    return true;
  }
  template <class U>
  bool operator!=(const VoxelAllocator<U>&) const noexcept {
    return false;
  }
};

// A volume's stored voxels (Volume::voxels) and the buffers that become them.
using VoxelVector = std::vector<int16_t, VoxelAllocator<int16_t>>;

// Equal values, whatever memory holds them (tests compare voxels with plain vectors).
inline bool operator==(const VoxelVector& a, const std::vector<int16_t>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end());
}
inline bool operator==(const std::vector<int16_t>& a, const VoxelVector& b) { return b == a; }
inline bool operator!=(const VoxelVector& a, const std::vector<int16_t>& b) { return !(a == b); }
inline bool operator!=(const std::vector<int16_t>& a, const VoxelVector& b) { return !(b == a); }

}  // namespace voxray
