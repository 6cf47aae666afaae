#include "voxray/io/volume.h"

#include <algorithm>

namespace voxray {

ValueRange storedRange(const Volume& v) {
  if (v.voxels.empty()) return {};
  // Values only, not their positions as std::minmax_element keeps: this loop vectorises
  // (0.73 G instructions became 0.08 G on a 512x512x400 CT: pacs get's output reports
  // the HU range, issue 39 item 8).
  int16_t lo = v.voxels[0], hi = lo;
  for (const int16_t x : v.voxels) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  return {lo, hi};
}

}  // namespace voxray
