#include "monotone_curve.h"

#include <algorithm>
#include <cmath>

namespace voxray {

namespace {

double sign(double v) { return double(v > 0.0) - double(v < 0.0); }

// Slopes of the points first ... last (distinct, increasing x) for a shape-preserving cubic.
void runSlopes(const std::vector<double>& x, const std::vector<double>& y, size_t first,
               size_t last, std::vector<double>& s) {
  size_t n = last - first + 1;
  if (n < 2) return;
  auto h = [&](size_t k) { return x[k + 1] - x[k]; };
  auto d = [&](size_t k) { return (y[k + 1] - y[k]) / h(k); };
  if (n == 2) {
    s[first] = s[last] = d(first);
    return;
  }
  for (size_t k = first + 1; k < last; ++k) {
    double d0 = d(k - 1), d1 = d(k);
    if (d0 * d1 <= 0.0) {
      s[k] = 0.0;  // a local extremum (or a flat side) stays flat: no overshoot
    } else {
      double w1 = 2.0 * h(k) + h(k - 1), w2 = h(k) + 2.0 * h(k - 1);
      s[k] = (w1 + w2) / (w1 / d0 + w2 / d1);
    }
  }
  // Ends: the three-point formula, limited so the end segment stays monotone.
  auto end = [&](double h0, double h1, double d0, double d1) {
    double e = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if (sign(e) != sign(d0)) return 0.0;
    if (sign(d0) != sign(d1) && std::abs(e) > 3.0 * std::abs(d0)) return 3.0 * d0;
    return e;
  };
  s[first] = end(h(first), h(first + 1), d(first), d(first + 1));
  s[last] = end(h(last - 1), h(last - 2), d(last - 1), d(last - 2));
}

}  // namespace

MonotoneCurve::MonotoneCurve(std::vector<double> x, std::vector<double> y, bool smooth)
    : x_(std::move(x)), y_(std::move(y)), slope_(x_.size(), 0.0), smooth_(smooth) {
  if (!smooth_) return;
  size_t first = 0;
  for (size_t k = 1; k <= x_.size(); ++k)
    if (k == x_.size() || x_[k] <= x_[k - 1]) {
      runSlopes(x_, y_, first, k - 1, slope_);
      first = k;
    }
}

double MonotoneCurve::onSegment(size_t i, double t) const {
  double h = x_[i + 1] - x_[i];
  double f = (t - x_[i]) / h;
  if (!smooth_) return (1.0 - f) * y_[i] + f * y_[i + 1];  // exact at both ends
  double f2 = f * f, f3 = f2 * f;
  return (2 * f3 - 3 * f2 + 1) * y_[i] + (f3 - 2 * f2 + f) * h * slope_[i] +
         (-2 * f3 + 3 * f2) * y_[i + 1] + (f3 - f2) * h * slope_[i + 1];
}

double MonotoneCurve::at(double t) const {
  if (x_.empty()) return 0.0;
  if (t < x_.front()) return y_.front();
  if (t >= x_.back()) return y_.back();
  // x_[i] <= t < x_[i + 1]: the last of coincident points, so a step takes its upper value.
  size_t i = size_t(std::upper_bound(x_.begin(), x_.end(), t) - x_.begin()) - 1;
  return onSegment(i, t);
}

double MonotoneCurve::leftOf(double t) const {
  if (x_.empty()) return 0.0;
  if (t <= x_.front()) return y_.front();
  if (t > x_.back()) return y_.back();
  // x_[i] < t <= x_[i + 1]: the first of coincident points.
  size_t i = size_t(std::lower_bound(x_.begin(), x_.end(), t) - x_.begin()) - 1;
  return onSegment(i, t);
}

}  // namespace voxray
