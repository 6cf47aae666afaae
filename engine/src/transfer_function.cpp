#include "voxray/engine/transfer_function.h"

#include <algorithm>
#include <cmath>

#include "gradient_table.h"
#include "voxray/io/volume.h"

namespace voxray {

glm::dvec4 TransferFunction::evaluate(double hu) const {
  if (points.empty()) return glm::dvec4(0.0);
  if (hu <= points.front().hu) return points.front().rgba;
  if (hu >= points.back().hu) return points.back().rgba;
  // First point strictly above hu; with coincident points this takes the upper one,
  // so a duplicated HU makes a clean step instead of a division by zero.
  auto hi = std::upper_bound(points.begin(), points.end(), hu,
                             [](double h, const ControlPoint& c) { return h < c.hu; });
  auto lo = hi - 1;
  double span = hi->hu - lo->hu;
  if (span <= 0.0) return hi->rgba;
  double f = (hu - lo->hu) / span;
  return glm::mix(lo->rgba, hi->rgba, f);
}

glm::dvec4 Lut::lookup(double stored) const {
  double last = double(rgba.size() - 1);
  double x = std::clamp((stored - storedMin) * scale, 0.0, last);
  double i = std::floor(x);
  double f = x - i;
  size_t k = size_t(i);
  glm::dvec4 a(rgba[k]);
  if (f == 0.0 || k + 1 >= rgba.size()) return a;
  return glm::mix(a, glm::dvec4(rgba[k + 1]), f);
}

Lut bakeLut(const TransferFunction& tf, const Volume& v, int maxEntries) {
  return bakeLut(tf, v, storedRange(v), maxEntries);
}

Lut bakeLut(const TransferFunction& tf, const Volume& v, const ValueRange& r, int maxEntries) {
  Lut lut;
  lut.storedMin = r.min;
  double span = double(r.max) - double(r.min);
  // One entry per stored unit where that fits: the table is then exact at every voxel.
  int entries = int(std::min<double>(std::max(2, maxEntries), span + 1.0));
  entries = std::max(entries, 2);
  lut.scale = span > 0.0 ? double(entries - 1) / span : 1.0;
  lut.rgba.resize(size_t(entries));
  for (int k = 0; k < entries; ++k) {
    double stored = lut.storedMin + double(k) / lut.scale;
    lut.rgba[size_t(k)] = glm::vec4(glm::clamp(tf.evaluate(v.toPhysical(stored)), 0.0, 1.0));
  }
  return lut;
}

double GradientTable::lookup(double storedPerMm) const {
  if (factor.empty()) return 1.0;
  double last = double(factor.size() - 1);
  double x = std::clamp(storedPerMm * scale, 0.0, last);
  double i = std::floor(x);
  size_t k = size_t(i);
  double a = factor[k];
  if (k + 1 >= factor.size()) return a;
  return a + (double(factor[k + 1]) - a) * (x - i);
}

GradientTable bakeGradientTable(const std::vector<glm::dvec2>& points, double slope) {
  GradientTable t;
  if (points.empty()) return t;
  // The factor at |gradient| g: linear between points, constant beyond; a repeated g makes
  // a step (the upper point wins, as TransferFunction::evaluate).
  auto at = [&](double g) {
    if (g <= points.front().x) return points.front().y;
    if (g >= points.back().x) return points.back().y;
    auto hi = std::upper_bound(points.begin(), points.end(), g,
                               [](double v, const glm::dvec2& p) { return v < p.x; });
    auto lo = hi - 1;
    double span = hi->x - lo->x;
    return span > 0.0 ? glm::mix(lo->y, hi->y, (g - lo->x) / span) : hi->y;
  };
  const int n = VOXRAY_GRADIENT_TABLE_ENTRIES;
  double maxHuPerMm = points.back().x > 0.0 ? points.back().x : 1.0;
  double huPerStored = std::abs(slope) > 0.0 ? std::abs(slope) : 1.0;
  t.scale = double(n - 1) * huPerStored / maxHuPerMm;
  t.factor.resize(size_t(n));
  for (int k = 0; k < n; ++k)
    t.factor[size_t(k)] = float(std::clamp(at(maxHuPerMm * double(k) / double(n - 1)), 0.0, 1.0));
  return t;
}

}  // namespace voxray
