#include "voxray/io/volume.h"

#include <algorithm>

namespace voxray {

ValueRange storedRange(const Volume& v) {
  if (v.voxels.empty()) return {};
  const auto [lo, hi] = std::minmax_element(v.voxels.begin(), v.voxels.end());
  return {*lo, *hi};
}

}  // namespace voxray
