#include "voxray/io/segment_mask.h"

#include <cmath>
#include <limits>

#include "parallel_rows.h"
#include "voxray/io/error.h"

namespace voxray {

StoredRange storedRangeOf(const Volume& v, HuRange range) {
  if (!std::isfinite(range.lo) || !std::isfinite(range.hi))
    throw inputError("The threshold range needs two numbers (LO,HI in " + v.unit + ").");
  if (range.lo > range.hi)
    throw inputError("The threshold range " + std::to_string(range.lo) + " to " +
                     std::to_string(range.hi) + " " + v.unit +
                     " is empty: give the lower value first (LO,HI).");
  // physical = stored * slope + intercept; a negative slope turns the range round.
  double a = v.toStored(range.lo), b = v.toStored(range.hi);
  if (a > b) std::swap(a, b);
  // A tolerance of 1e-9 stored units keeps a value exactly on the bound inside the range
  // despite the rounding of (physical - intercept) / slope.
  const double lo = std::ceil(a - 1e-9), hi = std::floor(b + 1e-9);
  StoredRange s;
  s.lo = int(std::max(lo, double(std::numeric_limits<int16_t>::min())));
  s.hi = int(std::min(hi, double(std::numeric_limits<int16_t>::max())));
  if (lo > std::numeric_limits<int16_t>::max() || hi < std::numeric_limits<int16_t>::min())
    s = StoredRange{};  // empty
  return s;
}

Mask thresholdMask(const Volume& v, HuRange range) {
  const StoredRange s = storedRangeOf(v, range);
  Mask m(v.voxelCount(), 0);
  const int16_t* in = v.voxels.data();
  parallelRange(v.dims.z, [&](int z0, int z1) {
    const size_t slice = size_t(v.dims.x) * size_t(v.dims.y);
    for (size_t i = size_t(z0) * slice; i < size_t(z1) * slice; ++i) m[i] = s.contains(in[i]);
  });
  return m;
}

Mask thresholdSlice(const Volume& v, int axis, int slice, HuRange range) {
  if (axis < 0 || axis > 2) throw inputError("A slice's axis is 0 (i), 1 (j) or 2 (k).");
  if (slice < 0 || slice >= v.dims[axis])
    throw inputError("Slice " + std::to_string(slice) + " is outside the volume (0 to " +
                     std::to_string(v.dims[axis] - 1) + " along " + "ijk"[axis] + ").");
  const StoredRange s = storedRangeOf(v, range);
  const int u = axis == 0 ? 1 : 0, w = axis == 2 ? 1 : 2;
  Mask m(size_t(v.dims[u]) * size_t(v.dims[w]), 0);
  glm::ivec3 p(0);
  p[axis] = slice;
  for (int b = 0; b < v.dims[w]; ++b) {
    p[w] = b;
    for (int a = 0; a < v.dims[u]; ++a) {
      p[u] = a;
      m[size_t(b) * size_t(v.dims[u]) + size_t(a)] = s.contains(v.at(p.x, p.y, p.z));
    }
  }
  return m;
}

}  // namespace voxray
