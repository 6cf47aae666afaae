#include "dvr_occupancy.h"

#include <algorithm>
#include <cmath>

namespace voxray {

DvrCellBounds dvrCellBounds(const std::vector<int>& opaqueBefore, float storedMin, float scale,
                            int lo, int hi) {
  DvrCellBounds b;
  b.lo = lo;
  if (hi < lo || opaqueBefore.size() < 2) return b;
  const int last = int(opaqueBefore.size()) - 2;  // the table's last entry
  const size_t n = size_t(hi - lo + 1);
  b.from.resize(n);
  b.to.resize(n);
  // classify's float steps in the same order, so the entries are the ones it picked.
  auto entry = [&](float value) {
    float x = (value - storedMin) * scale;
    return int(std::floor(std::clamp(x, 0.0f, float(last))));
  };
  for (size_t i = 0; i < n; ++i) {
    const float v = float(lo + int(i));
    const int first = std::max(entry(v - 0.5f) - 1, 0);
    const int lastRead = std::min(entry(v + 0.5f) + 2, last);
    b.from[i] = opaqueBefore[size_t(first)];
    b.to[i] = opaqueBefore[size_t(lastRead) + 1];
  }
  return b;
}

}  // namespace voxray
