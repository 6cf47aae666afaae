// The voxels' memory (voxel_memory.h): large blocks start on a 2 MiB boundary and are marked
// for transparent huge pages before their first write; small ones are plain allocations.
#include "voxray/io/voxel_memory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "voxray/io/volume.h"

namespace voxray {
namespace {

constexpr uintptr_t kTwoMiB = uintptr_t(2) << 20;

// The VmFlags line of the /proc/self/smaps mapping that holds P; empty when none does.
std::string vmFlagsAt(const void* p) {
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<uintptr_t>(p);
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    unsigned long lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
      inside = lo <= at && at < hi;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return {};
}

TEST(VoxelMemory, AVolumeSizedBlockIsZeroedAndStartsOnA2MiBBoundary) {
  // 3 MiB + 2 bytes: not a multiple of the huge page, so the rounding is exercised too.
  VoxelVector v((size_t(3) << 19) + 1);
  ASSERT_EQ(v.size(), (size_t(3) << 19) + 1);
#ifdef __linux__
  EXPECT_EQ(reinterpret_cast<uintptr_t>(v.data()) % kTwoMiB, 0u);
#endif
  size_t nonzero = 0;
  for (int16_t s : v) nonzero += s != 0;
  EXPECT_EQ(nonzero, 0u);
  v.back() = 1234;  // the last byte of the block is writable
  v.front() = -32768;
  VoxelVector copy = v;
  EXPECT_EQ(copy.back(), 1234);
  EXPECT_EQ(copy.front(), -32768);
  const int16_t* data = copy.data();
  VoxelVector moved = std::move(copy);
  EXPECT_EQ(moved.data(), data);  // a move keeps the block (the import moves it into Volume)
}

#ifdef __linux__
TEST(VoxelMemory, AVolumeSizedBlockIsMarkedForHugePages) {
  // "hg" in VmFlags: the range was given MADV_HUGEPAGE. Whether the kernel then backs it with
  // huge pages depends on free memory, so that is what the bench checks (AnonHugePages).
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  VoxelVector v(size_t(4) << 20);
  const std::string flags = vmFlagsAt(v.data());
  ASSERT_FALSE(flags.empty()) << "no mapping in /proc/self/smaps holds the block";
  EXPECT_NE((flags + " ").find(" hg "), std::string::npos) << flags;
}
#endif

TEST(VoxelMemory, SmallBlocksAreAllocatedToo) {
  VoxelVector v{1, 2, 3};
  v.push_back(4);
  EXPECT_EQ(v, (VoxelVector{1, 2, 3, 4}));
}

TEST(VoxelMemory, AVolumesVoxelsUseIt) {
  Volume volume;
  volume.dims = {512, 512, 4};
  volume.voxels.resize(volume.voxelCount());
#ifdef __linux__
  EXPECT_EQ(reinterpret_cast<uintptr_t>(volume.voxels.data()) % kTwoMiB, 0u);
#endif
  EXPECT_EQ(volume.byteSize(), size_t(2) << 20);
}

}  // namespace
}  // namespace voxray
