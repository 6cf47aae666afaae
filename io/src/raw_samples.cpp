#include "raw_samples.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <sstream>

namespace voxray::detail {
namespace {

constexpr double kStoredMin = -32768.0, kStoredMax = 32767.0;

template <class T>
T load(const uint8_t* p, bool swap) {
  using Bits = std::conditional_t<sizeof(T) == 2, uint16_t, uint32_t>;
  Bits bits;
  std::memcpy(&bits, p, sizeof bits);
  if (swap) {
    if constexpr (sizeof(T) == 2) {
      bits = __builtin_bswap16(bits);
    } else {
      bits = __builtin_bswap32(bits);
    }
  }
  return std::bit_cast<T>(bits);
}

// Calls f(i, hu) for every sample; one instantiation per type keeps the loops tight.
template <class F>
void visitSamples(const uint8_t* raw, size_t count, const RawLayout& layout, F&& f) {
  const bool swap = (layout.order == ByteOrder::Big) != (std::endian::native == std::endian::big);
  const double a = layout.slope, b = layout.intercept;
  switch (layout.type) {
    case SampleType::U8:
      for (size_t i = 0; i < count; ++i) f(i, raw[i] * a + b);
      break;
    case SampleType::I16:
      for (size_t i = 0; i < count; ++i) f(i, load<int16_t>(raw + 2 * i, swap) * a + b);
      break;
    case SampleType::U16:
      for (size_t i = 0; i < count; ++i) f(i, load<uint16_t>(raw + 2 * i, swap) * a + b);
      break;
    case SampleType::F32:
      for (size_t i = 0; i < count; ++i) f(i, double(load<float>(raw + 4 * i, swap)) * a + b);
      break;
  }
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

void ValueStats::merge(const ValueStats& o) {
  nonFinite += o.nonFinite;
  integral = integral && o.integral;
  if (!o.any) return;
  min = any ? std::min(min, o.min) : o.min;
  max = any ? std::max(max, o.max) : o.max;
  any = true;
}

ValueStats scanSamples(const uint8_t* raw, size_t count, const RawLayout& layout) {
  ValueStats s;
  double lo = INFINITY, hi = -INFINITY;
  visitSamples(raw, count, layout, [&](size_t, double v) {
    if (!std::isfinite(v)) {
      ++s.nonFinite;
      return;
    }
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    if (s.integral && v != std::nearbyint(v)) s.integral = false;
  });
  if (lo <= hi) {
    s.any = true;
    s.min = lo;
    s.max = hi;
  }
  return s;
}

Storage chooseStorage(const ValueStats& stats, const RawLayout& layout) {
  Storage st;
  const double lo = stats.any ? stats.min : 0.0, hi = stats.any ? stats.max : 0.0;
  st.fill = lo;  // NaN and infinities become the lowest value: empty space, like air
  if (stats.nonFinite > 0) {
    st.warning = std::to_string(stats.nonFinite) + " voxels were NaN or infinite; they were set " +
                 "to the lowest value, " + number(lo) + " (shown as empty). ";
  }

  // Rounding to whole units is harmless when it cannot merge two raw values: integer
  // samples with |slope| >= 1, or values that are whole already. Otherwise (f32 data, a
  // fine slope) a power-of-two step below 1 keeps the precision the data has.
  const bool integerSamples = layout.type != SampleType::F32;
  const bool roundable = stats.integral || (integerSamples && std::abs(layout.slope) >= 1.0);
  const bool fitsAsIs = std::round(lo) >= kStoredMin && std::round(hi) <= kStoredMax;
  if (roundable && fitsAsIs) return st;

  // Smallest power-of-two step that spans [lo, hi] in 65535 steps; fractional values keep
  // one step spare for rounding.
  const double span = roundable ? std::round(hi) - std::round(lo) : hi - lo;
  const double steps = roundable ? 65535.0 : 65534.0;
  int exponent = span > 0 ? int(std::ceil(std::log2(span / steps))) : 0;
  if (roundable) exponent = std::max(exponent, 0);
  st.slope = std::ldexp(1.0, exponent);
  const bool centred = lo / st.slope >= kStoredMin && hi / st.slope <= kStoredMax;
  // Shifting by lo + 32768 steps puts lo at the bottom of the 16-bit range.
  st.intercept = centred ? 0.0 : (roundable ? std::round(lo) : lo) + 32768.0 * st.slope;

  if (!fitsAsIs) {
    st.warning += "Values " + number(lo) + " to " + number(hi) +
                  " do not fit 16-bit voxels; they are stored with slope " + number(st.slope) +
                  " and intercept " + number(st.intercept) +
                  (st.slope > 1 ? " (precision " + number(st.slope) + ")." : " (no loss).");
  }
  return st;
}

void decodeSamples(const uint8_t* raw, size_t count, const RawLayout& layout, double* out) {
  visitSamples(raw, count, layout, [&](size_t i, double v) { out[i] = v; });
}

void storeSamples(const uint8_t* raw, size_t count, const RawLayout& layout, const Storage& storage,
                  int16_t* out) {
  const double inverse = 1.0 / storage.slope, offset = storage.intercept;
  const auto toStored = [&](double v) {
    const double s = std::nearbyint((v - offset) * inverse);
    return int16_t(std::clamp(s, kStoredMin, kStoredMax));
  };
  const int16_t fill = toStored(storage.fill);
  visitSamples(raw, count, layout,
               [&](size_t i, double v) { out[i] = std::isfinite(v) ? toStored(v) : fill; });
}

}  // namespace voxray::detail

namespace voxray {

size_t sampleBytes(SampleType t) {
  switch (t) {
    case SampleType::U8:
      return 1;
    case SampleType::I16:
    case SampleType::U16:
      return 2;
    case SampleType::F32:
      return 4;
  }
  return 0;
}

}  // namespace voxray
