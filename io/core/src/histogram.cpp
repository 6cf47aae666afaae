#include "voxray/io/histogram.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "voxray/io/parallel.h"
#include "voxray/io/volume.h"

namespace voxray {

uint64_t StoredHistogram::countIn(double lo, double hi) const {
  if (counts.empty()) return 0;
  double a = std::max(std::ceil(lo), double(min)), b = std::min(std::floor(hi), double(max));
  uint64_t sum = 0;
  for (double s = a; s <= b; s += 1.0) sum += counts[size_t(s - double(min))];
  return sum;
}

StoredHistogram storedHistogram(const Volume& v, const std::atomic<bool>* cancel) {
  constexpr size_t kValues = 65536;  // every int16
  const size_t n = v.voxels.size();
  // Chunks of 4 Mi voxels: each counts into its own table (256 KiB, in L2), then adds it
  // to the total once.
  constexpr size_t kChunk = size_t(1) << 22;
  const size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<uint64_t> all(kValues, 0);
  std::mutex merge;
  parallelFor(
      chunks,
      [&](size_t c) {
        std::vector<uint32_t> local(kValues, 0);
        const int16_t* p = v.voxels.data() + c * kChunk;
        const int16_t* end = v.voxels.data() + std::min(n, (c + 1) * kChunk);
        for (; p != end; ++p) ++local[size_t(int(*p) + 32768)];
        std::lock_guard<std::mutex> lock(merge);
        for (size_t k = 0; k < kValues; ++k) all[k] += local[k];
      },
      cancel);
  StoredHistogram h;
  if ((cancel && *cancel) || n == 0) return h;
  size_t first = 0, last = kValues - 1;
  while (all[first] == 0) ++first;
  while (all[last] == 0) --last;
  h.min = int16_t(int(first) - 32768);
  h.max = int16_t(int(last) - 32768);
  h.counts.assign(all.begin() + long(first), all.begin() + long(last) + 1);
  h.total = n;
  return h;
}

}  // namespace voxray
