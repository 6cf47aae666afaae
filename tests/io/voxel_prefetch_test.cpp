// VoxelPrefetch: pages made while a volume arrives are the ones its allocation gets, made
// before the import touches them; what nobody takes is released.
#include "voxel_prefetch.h"

#include <sys/mman.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <vector>

#include "test_support.h"
#include "voxray/io/voxel_memory.h"

namespace voxray {
namespace {

constexpr size_t kMiB = size_t(1) << 20;

// Bytes of [P, P + N) with pages in memory (mincore), without touching them.
size_t residentBytes(const void* p, size_t n) {
  const size_t page = size_t(sysconf(_SC_PAGESIZE));
  std::vector<unsigned char> in((n + page - 1) / page);
  if (mincore(const_cast<void*>(p), n, in.data()) != 0) return 0;
  size_t pages = 0;
  for (unsigned char c : in) pages += c & 1u;
  return pages * page;
}

// A block allocated as a volume's voxels are.
struct Block {
  size_t bytes;
  void* p;
  explicit Block(size_t n) : bytes(n), p(allocateVoxelMemory(n)) {}
  ~Block() { releaseVoxelMemory(p, bytes); }
};

// Waits (up to 20 s, for a loaded machine) until the thread has made BYTES of pages.
void waitUntilMade(const VoxelPrefetch& prefetch, size_t bytes) {
  for (int i = 0; i < 2000 && prefetch.made() < bytes; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(prefetch.made(), bytes);
}

TEST(VoxelPrefetch, TheVolumeGetsThePagesMadeWhileItArrived) {
  {
    VoxelPrefetch prefetch;
    prefetch.arrived(24 * kMiB);
    prefetch.arrived(64 * kMiB);
    prefetch.keep();
    waitUntilMade(prefetch, 64 * kMiB);
  }
  const Block volume(64 * kMiB);
  ASSERT_EQ(reinterpret_cast<uintptr_t>(volume.p) % (2 * kMiB), 0u);
  EXPECT_EQ(residentBytes(volume.p, volume.bytes), 64 * kMiB);  // made, not faulted here
  const auto* bytes = static_cast<const uint8_t*>(volume.p);
  size_t nonzero = 0;
  for (size_t i = 0; i < volume.bytes; ++i) nonzero += bytes[i] != 0;
  EXPECT_EQ(nonzero, 0u);
  // Taken once: the next block is made afresh.
  const Block next(64 * kMiB);
  EXPECT_EQ(residentBytes(next.p, next.bytes), 0u);
}

TEST(VoxelPrefetch, ARetrievalThatFailedKeepsNothing) {
  {
    VoxelPrefetch prefetch;  // no keep(): the retrieval did not complete
    prefetch.arrived(32 * kMiB);
    waitUntilMade(prefetch, 32 * kMiB);
  }
  const Block volume(32 * kMiB);
  EXPECT_EQ(residentBytes(volume.p, volume.bytes), 0u);
}

TEST(VoxelPrefetch, ScratchBuffersAndLateImportsDoNotTakeIt) {
  {
    VoxelPrefetch prefetch;
    prefetch.arrived(64 * kMiB);
    prefetch.keep(0.5);
    waitUntilMade(prefetch, 64 * kMiB);
  }
  {
    const Block scratch(8 * kMiB);  // under half of what arrived: not the volume
    EXPECT_EQ(residentBytes(scratch.p, scratch.bytes), 0u);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(800));  // past keep(0.5)
  const Block late(64 * kMiB);
  EXPECT_EQ(residentBytes(late.p, late.bytes), 0u);
}

}  // namespace
}  // namespace voxray
