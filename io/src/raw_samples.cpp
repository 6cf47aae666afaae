#include "raw_samples.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

#include "voxray/io/error.h"

namespace voxray::detail {
namespace {

constexpr double kStoredMin = -32768.0, kStoredMax = 32767.0;

template <class T>
T load(const uint8_t* p, bool swap) {
  using Bits = std::conditional_t<
      sizeof(T) == 1, uint8_t,
      std::conditional_t<sizeof(T) == 2, uint16_t,
                         std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>>;
  Bits bits;
  std::memcpy(&bits, p, sizeof bits);
  if (swap) {
    if constexpr (sizeof(T) == 2) {
      bits = __builtin_bswap16(bits);
    } else if constexpr (sizeof(T) == 4) {
      bits = __builtin_bswap32(bits);
    } else if constexpr (sizeof(T) == 8) {
      bits = __builtin_bswap64(bits);
    }
  }
  return std::bit_cast<T>(bits);
}

template <class T, class F>
void visitAs(const uint8_t* raw, size_t count, const SampleDecoding& d, F& f) {
  const double a = d.slope, b = d.intercept;
  for (size_t i = 0; i < count; ++i) f(i, double(load<T>(raw + sizeof(T) * i, d.swap)) * a + b);
}

// Calls f(i, hu) for every sample; one instantiation per type keeps the loops tight.
template <class F>
void visitSamples(const uint8_t* raw, size_t count, const SampleDecoding& d, F&& f) {
  using Visit = void (*)(const uint8_t*, size_t, const SampleDecoding&, F&);
  static constexpr Visit visits[] = {visitAs<uint8_t, F>,  visitAs<int8_t, F>,  // SampleKind order
                                     visitAs<uint16_t, F>, visitAs<int16_t, F>,
                                     visitAs<uint32_t, F>, visitAs<int32_t, F>,
                                     visitAs<float, F>,    visitAs<double, F>};
  visits[int(d.kind)](raw, count, d, f);
}

// Native 16-bit samples with slope 1 and a whole intercept (CT raw files, NRRD, NIfTI without
// scaling): scanned and stored in integer loops. Through doubles and nearbyint they took 40 %
// of a 1 GiB raw load (perf; issue 38's first image).
bool wholeI16(const SampleDecoding& d) {
  return d.kind == SampleKind::I16 && !d.swap && d.slope == 1.0 &&
         d.intercept == std::nearbyint(d.intercept) && std::fabs(d.intercept) < 1e9;
}

int16_t loadI16(const uint8_t* raw, size_t i) {
  int16_t v;
  std::memcpy(&v, raw + 2 * i, 2);
  return v;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

SampleKind kindOf(SampleType type) {
  switch (type) {
    case SampleType::U8:
      return SampleKind::U8;
    case SampleType::U16:
      return SampleKind::U16;
    case SampleType::F32:
      return SampleKind::F32;
    case SampleType::I16:
      break;
  }
  return SampleKind::I16;
}

SampleDecoding decodingOf(const RawLayout& layout) {
  SampleDecoding d;
  d.kind = kindOf(layout.type);
  d.swap = (layout.order == ByteOrder::Big) != (std::endian::native == std::endian::big);
  d.slope = layout.slope;
  d.intercept = layout.intercept;
  return d;
}

size_t sampleBytes(SampleKind kind) {
  static constexpr size_t bytes[] = {1, 1, 2, 2, 4, 4, 4, 8};  // in SampleKind order
  return bytes[int(kind)];
}

bool isIntegerKind(SampleKind kind) { return kind != SampleKind::F32 && kind != SampleKind::F64; }

void ValueStats::merge(const ValueStats& o) {
  nonFinite += o.nonFinite;
  integral = integral && o.integral;
  if (!o.any) return;
  min = any ? std::min(min, o.min) : o.min;
  max = any ? std::max(max, o.max) : o.max;
  any = true;
}

ValueStats scanSamples(const uint8_t* raw, size_t count, const SampleDecoding& decoding) {
  ValueStats s;
  if (wholeI16(decoding)) {
    int lo = INT16_MAX, hi = INT16_MIN;
    for (size_t i = 0; i < count; ++i) {
      const int v = loadI16(raw, i);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    if (count > 0) {
      s.any = true;
      s.min = lo + decoding.intercept;
      s.max = hi + decoding.intercept;
    }
    return s;
  }
  double lo = INFINITY, hi = -INFINITY;
  visitSamples(raw, count, decoding, [&](size_t, double v) {
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

Storage chooseStorage(const ValueStats& stats, const SampleDecoding& decoding) {
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
  const bool roundable =
      stats.integral || (isIntegerKind(decoding.kind) && std::abs(decoding.slope) >= 1.0);
  const bool fitsAsIs = std::round(lo) >= kStoredMin && std::round(hi) <= kStoredMax;
  if (roundable && fitsAsIs) return st;

  // Smallest power-of-two step that spans [lo, hi] in 65535 steps; fractional values keep
  // one step spare for rounding.
  const double span = roundable ? std::round(hi) - std::round(lo) : hi - lo;
  if (!std::isfinite(span))  // e.g. doubles near +-1.8e308, or a damaged scaling in a header
    throw inputError("values " + number(lo) + " to " + number(hi) +
                     " span more than a double can hold; the data or its scaling is damaged");
  const double steps = roundable ? 65535.0 : 65534.0;
  // Steps finer than 2^-1000 would make 1 / slope infinite (denormal data, a damaged
  // scaling; span / steps may even round to 0): the exponent stays at -1000 or above.
  const double wanted = span > 0 ? std::ceil(std::log2(span / steps)) : 0.0;
  int exponent = int(std::clamp(wanted, -1000.0, 1024.0));
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

void decodeSamples(const uint8_t* raw, size_t count, const SampleDecoding& decoding, double* out) {
  visitSamples(raw, count, decoding, [&](size_t i, double v) { out[i] = v; });
}

int16_t storedValue(double value, const Storage& storage) {
  // storeSamples' formula, the integer path's too (it gives the same for whole values).
  const double s = std::nearbyint((value - storage.intercept) * (1.0 / storage.slope));
  return int16_t(std::clamp(s, kStoredMin, kStoredMax));
}

void storeSamples(const uint8_t* raw, size_t count, const SampleDecoding& decoding,
                  const Storage& storage, int16_t* out) {
  if (wholeI16(decoding) && storage.slope == 1.0 &&
      storage.intercept == std::nearbyint(storage.intercept) &&
      std::fabs(storage.intercept) < 1e9) {
    // stored = raw + intercept - storage intercept, exactly as the rounding below gives it.
    const int delta = int(decoding.intercept - storage.intercept);
    if (delta == 0 && static_cast<const void*>(raw) == static_cast<const void*>(out))
      return;  // read into the voxels in place and already what they store
    for (size_t i = 0; i < count; ++i)
      out[i] = int16_t(std::clamp(int(loadI16(raw, i)) + delta, -32768, 32767));
    return;
  }
  const double inverse = 1.0 / storage.slope, offset = storage.intercept;
  const auto toStored = [&](double v) {
    const double s = std::nearbyint((v - offset) * inverse);
    return int16_t(std::clamp(s, kStoredMin, kStoredMax));
  };
  const int16_t fill = toStored(storage.fill);
  visitSamples(raw, count, decoding,
               [&](size_t i, double v) { out[i] = std::isfinite(v) ? toStored(v) : fill; });
}

}  // namespace voxray::detail

namespace voxray {

size_t sampleBytes(SampleType t) { return detail::sampleBytes(detail::kindOf(t)); }

}  // namespace voxray
