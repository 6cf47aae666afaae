#include "voxel_prefetch.h"

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace voxray {

struct VoxelPrefetch::State {
  std::mutex m;
  std::condition_variable changed;
  uint8_t* base = nullptr;  // 2 MiB-aligned
  size_t capacity = 0;      // bytes of address space at BASE
  size_t arrived = 0, made = 0;
  bool busy = false;     // the thread is making pages now
  bool taken = false;    // an allocation owns BASE
  bool done = false;     // no more bytes will arrive
  bool dropped = false;  // released (or being released) by the thread
  std::chrono::steady_clock::time_point until;
};

namespace {

using State = VoxelPrefetch::State;
constexpr size_t kHugePage = size_t(2) << 20;
// Addresses only (no memory is committed until pages are made), enough for any volume the
// import would allocate; pages are made for at most kMaxPrefetch bytes.
constexpr size_t kAddressSpace = size_t(64) << 30;
constexpr size_t kMaxPrefetch = size_t(4) << 30;
constexpr size_t kStep = size_t(8) << 20;

std::mutex gMutex;
std::weak_ptr<State> gWaiting;  // the prefetch an allocation may take (the newest)

void makePages(uint8_t* p, size_t n) {
#if defined(MADV_POPULATE_WRITE)
  if (madvise(p, n, MADV_POPULATE_WRITE) == 0) return;
#endif
  // Older kernels: a write per page makes it (the memory is zero, and stays so).
  for (size_t i = 0; i < n; i += 4096) reinterpret_cast<volatile uint8_t*>(p)[i] = 0;
}

// Makes pages up to what has arrived; after done, waits until UNTIL for an allocation to
// take them, then releases them.
void run(const std::shared_ptr<State>& s) {
  std::unique_lock lock(s->m);
  for (;;) {
    if (s->taken) return;
    const size_t want = std::min(s->arrived, std::min(s->capacity, kMaxPrefetch));
    if (s->made < want) {
      const size_t from = s->made, n = std::min(kStep, want - from);
      s->busy = true;
      lock.unlock();
      makePages(s->base + from, n);
      lock.lock();
      s->busy = false;
      s->made = from + n;
      s->changed.notify_all();
      continue;
    }
    if (s->done && std::chrono::steady_clock::now() >= s->until) break;
    if (s->done)
      s->changed.wait_until(lock, s->until);
    else
      s->changed.wait(lock);
  }
  s->dropped = true;
  lock.unlock();
#if defined(__linux__)
  munmap(s->base, s->capacity);
#endif
}

}  // namespace

#if defined(__linux__)
VoxelPrefetch::VoxelPrefetch() {
  void* m = mmap(nullptr, kAddressSpace + kHugePage, PROT_READ | PROT_WRITE,
                 MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (m == MAP_FAILED) return;  // no prefetch: the import makes its pages itself
  const auto raw = reinterpret_cast<uintptr_t>(m);
  const uintptr_t start = (raw + kHugePage - 1) & ~(kHugePage - 1);
  if (start > raw) munmap(m, start - raw);
  if (const size_t tail = raw + kHugePage - start; tail > 0)
    munmap(reinterpret_cast<void*>(start + kAddressSpace), tail);
  madvise(reinterpret_cast<void*>(start), kAddressSpace, MADV_HUGEPAGE);
  state_ = std::make_shared<State>();
  state_->base = reinterpret_cast<uint8_t*>(start);
  state_->capacity = kAddressSpace;
  {
    std::lock_guard g(gMutex);
    gWaiting = state_;
  }
  std::thread([s = state_] { run(s); }).detach();
}
#else
VoxelPrefetch::VoxelPrefetch() = default;
#endif

VoxelPrefetch::~VoxelPrefetch() {
  if (!state_) return;
  std::lock_guard lock(state_->m);
  state_->done = true;
  state_->until = std::chrono::steady_clock::now() + (keep_ ? keepFor_ : std::chrono::seconds(0));
  state_->changed.notify_all();
}

void VoxelPrefetch::arrived(size_t bytes) {
  if (!state_) return;
  std::lock_guard lock(state_->m);
  if (bytes <= state_->arrived) return;
  state_->arrived = bytes;
  state_->changed.notify_all();
}

void VoxelPrefetch::keep(double keepSeconds) {
  keep_ = true;
  keepFor_ = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(keepSeconds));
}

size_t VoxelPrefetch::made() const {
  if (!state_) return 0;
  std::lock_guard lock(state_->m);
  return state_->made;
}

void* takePrefetchedVoxels(size_t bytes) {
  std::shared_ptr<State> s;
  {
    std::lock_guard g(gMutex);
    s = gWaiting.lock();
  }
  if (!s) return nullptr;
  std::unique_lock lock(s->m);
  // Only a block the size of what arrived is that volume (not a scratch buffer before it).
  const bool expired = s->done && std::chrono::steady_clock::now() >= s->until;
  if (s->taken || s->dropped || expired || bytes == 0 || bytes > s->capacity ||
      bytes < s->arrived / 2)
    return nullptr;
  s->changed.wait(lock, [&] { return !s->busy; });
  s->taken = true;
  s->changed.notify_all();
  lock.unlock();
  {
    std::lock_guard g(gMutex);
    if (gWaiting.lock() == s) gWaiting.reset();
  }
#if defined(__linux__)
  munmap(s->base + bytes, s->capacity - bytes);
#endif
  return s->base;
}

}  // namespace voxray
