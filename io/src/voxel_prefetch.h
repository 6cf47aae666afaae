#pragma once
// Memory for a volume that is still arriving (a PACS retrieval). Zeroing a CT's 200 MB of
// fresh pages is a third of its import's CPU time; while the transfer waits on the network
// the client's cores are mostly idle, so a background thread makes those pages as the bytes
// arrive, and the import's allocation (allocateVoxelMemory) takes them ready.
#include <chrono>
#include <cstddef>
#include <memory>

namespace voxray {

class VoxelPrefetch {
 public:
  VoxelPrefetch();
  // Released at once unless keep() was called; then it waits a while for the import.
  ~VoxelPrefetch();
  VoxelPrefetch(const VoxelPrefetch&) = delete;
  VoxelPrefetch& operator=(const VoxelPrefetch&) = delete;

  // BYTES of the volume's files have arrived so far (their voxels take about as much).
  void arrived(size_t bytes);
  // Bytes of pages made so far.
  size_t made() const;
  // The retrieval is complete: the pages wait up to KEEP_SECONDS for the import, then go.
  void keep(double keepSeconds = 30.0);

  struct State;

 private:
  std::shared_ptr<State> state_;
  bool keep_ = false;
  std::chrono::steady_clock::duration keepFor_{};
};

// Pages made ready for a block of exactly BYTES (a multiple of 2 MiB, at least half of what
// arrived), 2 MiB-aligned and zeroed, or null when none wait; the caller owns them
// (releaseVoxelMemory).
void* takePrefetchedVoxels(size_t bytes);

}  // namespace voxray
