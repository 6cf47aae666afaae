#pragma once
// How many voxels hold each stored value: the histogram a transfer-function editor draws its
// curves over (issue 35). Exact (one count per stored value), so any binning of the HU axis
// is a sum of counts, made when it is drawn.
#include <atomic>
#include <cstdint>
#include <vector>

namespace voxray {

struct Volume;

struct StoredHistogram {
  int16_t min = 0, max = 0;      // the stored values counted: min ... max
  std::vector<uint64_t> counts;  // counts[s - min] voxels hold stored value s
  uint64_t total = 0;
  bool empty() const { return counts.empty(); }
  // Voxels whose stored value lies in [lo, hi] (clamped to min ... max).
  uint64_t countIn(double lo, double hi) const;
};

// Counts V's voxels on every core. Returns an empty histogram when *CANCEL turns true (the
// volume was closed or replaced meanwhile).
StoredHistogram storedHistogram(const Volume& v, const std::atomic<bool>* cancel = nullptr);

}  // namespace voxray
