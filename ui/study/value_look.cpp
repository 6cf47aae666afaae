#include "value_look.h"

#include <algorithm>
#include <cstdint>
#include <limits>

#include "voxray/io/volume.h"

namespace voxray {

namespace {

// The stored value below which a fraction Q of COUNTS (a histogram over every int16 value)
// lies.
int16_t storedQuantile(const std::vector<uint64_t>& counts, uint64_t total, double q) {
  const auto rank = uint64_t(q * double(total));
  uint64_t below = 0;
  for (size_t i = 0; i < counts.size(); ++i) {
    below += counts[i];
    if (below > rank) return int16_t(int(i) + std::numeric_limits<int16_t>::min());
  }
  return std::numeric_limits<int16_t>::max();
}

}  // namespace

bool valuesAreHu(const Volume& v) {
  // An MR or a PET is never HU, whatever its unit field says (Volume's default is "HU").
  return v.modality == "CT" || (v.modality.empty() && v.unit == "HU");
}

std::string valueUnit(const Volume& v) {
  if (valuesAreHu(v)) return "HU";
  return v.unit.empty() ? "value" : v.unit;
}

std::string valueUnitLabel(const Volume& v) {
  // "MR signal (scanner units)" and the like say only that the unit is not known.
  constexpr size_t kLabelChars = 8;
  std::string unit = valueUnit(v);
  return unit.size() <= kLabelChars && unit.find("unit") == std::string::npos ? unit : "value";
}

ValueLook valueLook(const Volume& v) {
  std::vector<uint64_t> counts(size_t(1) << 16, 0);
  // Every voxel of a volume up to 16 M; a regular subset of a larger one (the percentiles
  // of a few million voxels differ from all by far less than the ramp's width).
  const size_t n = v.voxels.size();
  const size_t stride = std::max<size_t>(1, n / (size_t(1) << 24));
  uint64_t total = 0;
  for (size_t i = 0; i < n; i += stride, ++total)
    ++counts[size_t(int(v.voxels[i]) - std::numeric_limits<int16_t>::min())];
  ValueLook look;
  if (total == 0) return look;
  double a = v.toPhysical(storedQuantile(counts, total, 0.01));
  double b = v.toPhysical(storedQuantile(counts, total, 0.995));
  if (a > b) std::swap(a, b);     // a negative slope
  if (b - a < 1e-6) b = a + 1.0;  // a constant volume: a ramp of one unit
  look.low = a;
  look.high = b;
  look.threshold = a + 0.25 * (b - a);
  return look;
}

void applyValueLook(RenderParams& p, const ValueLook& look) {
  p.isoLo = look.threshold;
  p.isoHi = std::max(32767.0, 2.0 * look.high - look.low);  // above every voxel
  p.preset.clear();
  p.presetShiftHu = 0.0;
  // Opacity 0.05 per voxel at the bright end: a brain's surface shows, and its inside
  // shines through a little, as a CT's soft-tissue preset does.
  p.transferFunction = {{look.threshold, {1.0, 1.0, 1.0, 0.0}}, {look.high, {1.0, 1.0, 1.0, 0.05}}};
  p.opacityUnitMm = 0.0;  // 0.05 per voxel
  p.windowWidth = look.high - look.low;
  p.windowLevel = 0.5 * (look.low + look.high);
}

}  // namespace voxray
