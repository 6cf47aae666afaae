#include "axis_zoom.h"

#include <algorithm>
#include <cmath>

#include "voxray/io/histogram.h"

namespace voxray {

double axisPixel(const AxisRange& r, double value, double p0, double length) {
  return p0 + (value - r.lo) / r.span() * length;
}

double axisValue(const AxisRange& r, double pixel, double p0, double length) {
  return r.lo + (pixel - p0) / length * r.span();
}

AxisRange zoomAbout(const AxisRange& r, double value, double factor, double minSpan,
                    double maxSpan) {
  if (!std::isfinite(value) || !std::isfinite(factor) || factor <= 0.0 || !(r.span() > 0.0))
    return r;
  const double span = std::clamp(r.span() * factor, minSpan, std::max(minSpan, maxSpan));
  const double f = span / r.span();
  // VALUE divides the axis in the same proportion before and after: it keeps its pixel.
  return {value - (value - r.lo) * f, value + (r.hi - value) * f};
}

double wheelZoomFactor(double notches) { return std::pow(0.8, notches); }

AxisRange panByPixels(const AxisRange& r, double pixels, double length) {
  if (length == 0.0 || !std::isfinite(pixels)) return r;
  const double d = pixels / length * r.span();
  return {r.lo - d, r.hi - d};
}

AxisRange occupiedRange(const std::vector<uint64_t>& counts, double lo, double hi,
                        double fraction) {
  uint64_t total = 0;
  for (uint64_t c : counts) total += c;
  if (counts.empty() || total == 0) return {lo, hi};
  const double need = std::max(1.0, fraction * double(total));
  size_t first = counts.size(), last = 0;
  for (size_t i = 0; i < counts.size(); ++i)
    if (double(counts[i]) >= need) {
      first = std::min(first, i);
      last = i;
    }
  if (first == counts.size()) return {lo, hi};  // spread thinner than FRACTION everywhere
  const double width = (hi - lo) / double(counts.size());
  return {lo + width * double(first), lo + width * double(last + 1)};
}

AxisRange visibleHuRange(const StoredHistogram& h, double slope, double intercept, double fraction,
                         int bins) {
  const double a = h.min * slope + intercept, b = (h.max + 1) * slope + intercept;
  const double lo = std::min(a, b), hi = std::max(a, b);
  if (h.empty() || bins < 1 || slope == 0.0) return {lo, hi};
  std::vector<uint64_t> counts(size_t(bins), 0);
  const double width = (hi - lo) / bins;
  for (size_t k = 0; k < h.counts.size(); ++k) {
    // A stored value s stands for HU s*slope+intercept ... one step up: its bin is that of
    // its lower edge (the whole axis is [min, max+1) in stored steps).
    const double hu = (double(h.min) + double(k)) * slope + intercept;
    const double edge = slope > 0 ? hu : hu + slope;
    const int bin = std::clamp(int(std::floor((edge - lo) / width)), 0, bins - 1);
    counts[size_t(bin)] += h.counts[k];
  }
  return occupiedRange(counts, lo, hi, fraction);
}

}  // namespace voxray
