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

// What storeSlice and storeWords share: the slice's scale, its padding range and air.
struct Mapping {
  int32_t offset;
  SliceScale scale;
  int32_t padLo = 1, padHi = 0;  // empty range: no padding
  int16_t air;

  Mapping(const FrameHeader& h, double airPhysical)
      : offset((h.pixelRepresentation == 0 && h.bitsStored > 15) ? 32768 : 0) {
    scale.slope = h.slope;
    scale.intercept = h.intercept + double(offset) * h.slope;
    if (h.padding) {
      padLo = padHi = *h.padding;
      if (h.paddingLimit) {
        padLo = std::min(*h.padding, *h.paddingLimit);
        padHi = std::max(*h.padding, *h.paddingLimit);
      }
    }
    air = clamp16((airPhysical - scale.intercept) / scale.slope);
  }
};

}  // namespace

double airValue(const std::string& modality) { return modality == "CT" ? -1024.0 : 0.0; }

SliceScale storeSlice(const std::vector<int32_t>& values, const FrameHeader& h, double airPhysical,
                      int16_t* out) {
  const Mapping m(h, airPhysical);
  const int32_t offset = m.offset, padLo = m.padLo, padHi = m.padHi;
  const int16_t air = m.air;
  SliceScale s = m.scale;
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

SliceScale storeWords(uint16_t* words, size_t count, const FrameHeader& h, double airPhysical) {
  const Mapping m(h, airPhysical);
  // PixelFile's masking to BitsStored and sign extension (16 bits: the word as it is).
  const int bits = std::clamp(h.bitsStored, 1, 16);
  const uint32_t mask = uint32_t((1u << bits) - 1u);
  const uint32_t sign = h.pixelRepresentation == 1 ? uint32_t(1u << (bits - 1)) : 0u;
  const int32_t offset = m.offset, padLo = m.padLo, padHi = m.padHi;
  const int16_t air = m.air;
  auto* out = reinterpret_cast<int16_t*>(words);
  int16_t lo = INT16_MAX, hi = INT16_MIN;
  auto range = [&] {
    SliceScale s = m.scale;
    s.min = count == 0 ? 0 : lo;
    s.max = count == 0 ? 0 : hi;
    return s;
  };
  if (bits == 16 && (sign != 0 || offset == 32768)) {
    // The common case in 16-bit lanes: the voxel is the word (signed) or the word minus
    // 32768 (unsigned), which is the word with its top bit flipped; padding in that domain.
    const auto flip = uint16_t(offset == 32768 ? 0x8000 : 0);
    const int32_t plo = std::max(padLo - offset, -32768), phi = std::min(padHi - offset, 32767);
    if (plo <= phi) {
      for (size_t i = 0; i < count; ++i) {
        int16_t o = int16_t(words[i] ^ flip);
        o = (o >= plo && o <= phi) ? air : o;
        out[i] = o;
        lo = std::min(lo, o);
        hi = std::max(hi, o);
      }
    } else {
      for (size_t i = 0; i < count; ++i) {
        const auto o = int16_t(words[i] ^ flip);
        out[i] = o;
        lo = std::min(lo, o);
        hi = std::max(hi, o);
      }
    }
    return range();
  }
  // One branch-free pass (vectorised): each word is read before its slot is written.
  for (size_t i = 0; i < count; ++i) {
    const int32_t v = int32_t((uint32_t(words[i]) & mask) ^ sign) - int32_t(sign);
    int16_t o = int16_t(std::clamp(v - offset, -32768, 32767));
    o = (v >= padLo && v <= padHi) ? air : o;
    out[i] = o;
    lo = std::min(lo, o);
    hi = std::max(hi, o);
  }
  return range();
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
