#include "voxray/engine/transfer_function.h"

#include <algorithm>
#include <cmath>

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

}  // namespace voxray
