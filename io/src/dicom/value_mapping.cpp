#include "value_mapping.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace voxray::dicom {
namespace {

int16_t clamp16(double v) {
  return int16_t(std::clamp(std::lround(v), long(INT16_MIN), long(INT16_MAX)));
}

bool integral(double v) { return std::abs(v - std::round(v)) < 1e-9; }

}  // namespace

double airValue(const std::string& modality) { return modality == "CT" ? -1024.0 : 0.0; }

SliceScale storeSlice(const std::vector<int32_t>& values, const FrameHeader& h, double airPhysical,
                      int16_t* out) {
  const int32_t offset = (h.pixelRepresentation == 0 && h.bitsStored > 15) ? 32768 : 0;
  SliceScale s;
  s.slope = h.slope;
  s.intercept = h.intercept + double(offset) * h.slope;
  int32_t padLo = 1, padHi = 0;  // empty range: no padding
  if (h.padding) {
    padLo = padHi = *h.padding;
    if (h.paddingLimit) {
      padLo = std::min(*h.padding, *h.paddingLimit);
      padHi = std::max(*h.padding, *h.paddingLimit);
    }
  }
  const int16_t air = clamp16((airPhysical - s.intercept) / s.slope);
  // Branch-free loops (vectorised): this runs on every voxel of the volume.
  const size_t n = values.size();
  const int32_t* in = values.data();
  for (size_t i = 0; i < n; ++i) out[i] = int16_t(std::clamp(in[i] - offset, -32768, 32767));
  if (padLo <= padHi)
    for (size_t i = 0; i < n; ++i)
      if (in[i] >= padLo && in[i] <= padHi) out[i] = air;
  int16_t lo = INT16_MAX, hi = INT16_MIN;
  for (size_t i = 0; i < n; ++i) {
    lo = std::min(lo, out[i]);
    hi = std::max(hi, out[i]);
  }
  s.min = values.empty() ? 0 : lo;
  s.max = values.empty() ? 0 : hi;
  return s;
}

CommonScale chooseCommonScale(const std::vector<SliceScale>& slices) {
  CommonScale c;
  if (slices.empty()) return c;
  c.slope = slices[0].slope;
  c.intercept = slices[0].intercept;
  bool same = true, allIntegral = true;
  double minSlope = 1e300, maxSlope = -1e300, minIcpt = 1e300, maxIcpt = -1e300;
  double lo = 1e300, hi = -1e300;
  for (auto& s : slices) {
    same &= s.slope == c.slope && s.intercept == c.intercept;
    allIntegral &= integral(s.slope) && integral(s.intercept);
    minSlope = std::min(minSlope, std::abs(s.slope));
    maxSlope = std::max(maxSlope, std::abs(s.slope));
    minIcpt = std::min(minIcpt, s.intercept);
    maxIcpt = std::max(maxIcpt, s.intercept);
    double a = s.min * s.slope + s.intercept, b = s.max * s.slope + s.intercept;
    lo = std::min({lo, a, b});
    hi = std::max({hi, a, b});
  }
  if (same) return c;
  c.remap = true;
  c.slope = allIntegral ? 1.0 : minSlope;
  bool coarser = false;
  if ((hi - lo) / c.slope > 65535.0) {
    c.slope = (hi - lo) / 65535.0;
    coarser = true;
  }
  c.intercept =
      (lo / c.slope >= -32768.0 && hi / c.slope <= 32767.0) ? 0.0 : lo + 32768.0 * c.slope;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "rescale differs between slices (slope %g to %g, intercept %g to %g): values "
                "kept on one scale with step %g%s",
                minSlope, maxSlope, minIcpt, maxIcpt, c.slope,
                allIntegral ? " (exact)"
                : coarser   ? " (the value range forced a coarser step than any slice)"
                            : " (the finest slice step; others rounded to it)");
  c.warning = buf;
  return c;
}

void remapSlice(int16_t* data, size_t count, const SliceScale& from, const CommonScale& to) {
  const double a = from.slope / to.slope, b = (from.intercept - to.intercept) / to.slope;
  for (size_t i = 0; i < count; ++i) data[i] = clamp16(data[i] * a + b);
}

}  // namespace voxray::dicom
