#include "voxray/io/voxel_memory.h"

#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace voxray {

namespace {

constexpr size_t kHugePage = size_t(2) << 20;

size_t roundUp(size_t bytes) { return (bytes + kHugePage - 1) & ~(kHugePage - 1); }

}  // namespace

#if defined(__linux__)

void* allocateVoxelMemory(size_t bytes) {
  if (bytes < kHugePage) return std::memset(::operator new(bytes), 0, bytes);
  // One huge page more than needed, the unaligned head and the tail given back: the block
  // starts on a 2 MiB boundary, so every 2 MiB of it can be one page.
  const size_t size = roundUp(bytes);
  if (size < bytes || size + kHugePage < size) throw std::bad_alloc();
  void* m =
      mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (m == MAP_FAILED) throw std::bad_alloc();
  const auto base = reinterpret_cast<uintptr_t>(m);
  const uintptr_t start = (base + kHugePage - 1) & ~(kHugePage - 1);
  if (start > base) munmap(m, start - base);
  if (const size_t tail = base + size + kHugePage - (start + size); tail > 0)
    munmap(reinterpret_cast<void*>(start + size), tail);
  // Before the first write, so that the page faults take huge pages; a kernel without THP
  // refuses and the block keeps 4 KiB pages.
  madvise(reinterpret_cast<void*>(start), size, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(start);
}

void releaseVoxelMemory(void* p, size_t bytes) noexcept {
  if (!p) return;
  if (bytes < kHugePage) {
    ::operator delete(p);
    return;
  }
  munmap(p, roundUp(bytes));
}

#else

void* allocateVoxelMemory(size_t bytes) { return std::memset(::operator new(bytes), 0, bytes); }
void releaseVoxelMemory(void* p, size_t) noexcept { ::operator delete(p); }

#endif

}  // namespace voxray
