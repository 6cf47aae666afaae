#pragma once
// Thresholds in physical units (HU for CT) that make a binary mask on the volume's grid,
// and the one-slice preview the editor draws while the user drags the range.
#include <cstdint>
#include <vector>

#include "voxray/io/segmentation.h"

namespace voxray {

// One byte per voxel of a grid, x fastest: 1 inside, 0 outside.
using Mask = std::vector<uint8_t>;

// An inclusive range of physical values (HU for CT).
struct HuRange {
  double lo = 0.0;
  double hi = 0.0;
};

// The stored (int16) values of the volume that fall inside the physical range, clamped to
// int16; empty (lo > hi) when none does. Throws an input Error when range.lo > range.hi or
// either is not a number.
struct StoredRange {
  int lo = 0, hi = -1;
  bool contains(int16_t v) const { return v >= lo && v <= hi; }
  bool empty() const { return lo > hi; }
};
StoredRange storedRangeOf(const Volume& v, HuRange range);

// Every voxel whose value lies in the range. Throws as storedRangeOf.
Mask thresholdMask(const Volume& v, HuRange range);

// The threshold of one slice (axis 0 = i, 1 = j, 2 = k; the slice index along it), as a 2D
// mask of the slice's two other axes, the lower axis fastest. Throws an input Error for a
// slice outside the volume or a bad range.
Mask thresholdSlice(const Volume& v, int axis, int slice, HuRange range);

}  // namespace voxray
