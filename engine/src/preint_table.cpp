#include "voxray/engine/preint_table.h"

#include <algorithm>
#include <cmath>

#include "preint_table.h"

namespace voxray {

namespace {

constexpr int kSize = VOXRAY_PREINT_VALUES;
// An opacity of 1 has no finite depth: this many halvings of the light leave less than float
// can hold (2^-200 == 0), even over a sixteenth of the reference step.
constexpr double kOpaqueDepth = 200.0 * 16.0;

}  // namespace

int PreintTable::size() { return kSize; }

double PreintTable::alphaAt(int i, int j) const {
  return 1.0 - std::exp2(-double(rgba[size_t(i) * kSize + size_t(j)].a));
}

glm::dvec4 PreintTable::lookup(double vf, double vb, double segRatio) const {
  if (empty()) return glm::dvec4(0.0);
  const double last = kSize - 1;
  double xf = (vf - storedLo) * perStored, xb = (vb - storedLo) * perStored;
  double cf = std::clamp(xf, 0.0, last), cb = std::clamp(xb, 0.0, last);
  double f0 = std::floor(cf), b0 = std::floor(cb);
  int i = int(f0), j = int(b0), i1 = std::min(i + 1, kSize - 1), j1 = std::min(j + 1, kSize - 1);
  auto at = [&](int r, int c) { return glm::dvec4(rgba[size_t(r) * kSize + size_t(c)]); };
  double fx = cb - b0;
  glm::dvec4 e =
      glm::mix(glm::mix(at(i, j), at(i, j1), fx), glm::mix(at(i1, j), at(i1, j1), fx), cf - f0);
  double run = std::abs(xb - xf);
  double inside = run > 0.0 ? std::abs(cb - cf) / run : 1.0;
  e.a = 1.0 - std::exp2(-e.a * inside * segRatio);
  return e;
}

PreintTable bakePreintTable(const Lut& lut, double ratio) {
  PreintTable t;
  t.ratio = ratio;
  const int entries = int(lut.rgba.size());
  if (entries < 2) return t;
  // Optical depth per reference step (log2 units) and colour at each entry, linear between
  // entries (the depth's interpolation stands in for the colour table's opacity's).
  std::vector<double> depth(static_cast<size_t>(entries));
  int first = -1, lastShown = -1;
  for (int k = 0; k < entries; ++k) {
    double a = std::clamp(double(lut.rgba[size_t(k)].a), 0.0, 1.0);
    depth[size_t(k)] = a >= 1.0 ? kOpaqueDepth : std::min(-std::log2(1.0 - a), kOpaqueDepth);
    if (a > 0.0) {
      if (first < 0) first = k;
      lastShown = k;
    }
  }
  // Rows and columns on entries, from one transparent entry before the first that shows to
  // one after the last, a whole number of entries apart.
  const int lo = first < 0 ? 0 : std::max(first - 1, 0);
  const int hi = first < 0 ? entries - 1 : std::min(lastShown + 1, entries - 1);
  const int step = std::max(1, (hi - lo + kSize - 2) / (kSize - 1));
  t.entriesPerBin = step;
  t.storedLo = lut.storedMin + double(lo) / lut.scale;
  t.perStored = lut.scale / double(step);
  // Prefix sums: the depth's integral and the depth-weighted colour's from entry 0 (trapezoids,
  // exact for the depth linear between entries).
  std::vector<double> depthSum(size_t(entries), 0.0);
  std::vector<glm::dvec3> colourSum(size_t(entries), glm::dvec3(0.0));
  auto colour = [&](int k) { return glm::dvec3(lut.rgba[size_t(k)]); };
  for (int k = 1; k < entries; ++k) {
    size_t a = size_t(k - 1), b = size_t(k);
    depthSum[b] = depthSum[a] + 0.5 * (depth[a] + depth[b]);
    colourSum[b] = colourSum[a] + 0.5 * (depth[a] * colour(k - 1) + depth[b] * colour(k));
  }
  // Row r's entry, its prefix sums (past the table's end the last entry holds, as lookup's clamp).
  struct Row {
    double x, sum, depth;
    glm::dvec3 colourSum, colour;
  };
  std::vector<Row> rows(kSize);
  const int end = entries - 1;
  for (int r = 0; r < kSize; ++r) {
    int x = lo + r * step, k = std::min(x, end);
    double beyond = double(x - k);
    rows[size_t(r)] = {double(x), depthSum[size_t(k)] + beyond * depth[size_t(k)], depth[size_t(k)],
                       colourSum[size_t(k)] + beyond * depth[size_t(k)] * colour(k), colour(k)};
  }
  t.rgba.resize(size_t(kSize) * kSize);
  for (int i = 0; i < kSize; ++i)
    for (int j = 0; j < kSize; ++j) {
      const Row &f = rows[size_t(i)], &b = rows[size_t(j)];
      double meanDepth;
      glm::dvec3 c;
      if (i == j) {
        meanDepth = f.depth;
        c = f.colour;
      } else {
        double integral = b.sum - f.sum;  // signed like b.x - f.x
        meanDepth = integral / (b.x - f.x);
        c = std::abs(integral) > 1e-12 ? (b.colourSum - f.colourSum) / integral
                                       : 0.5 * (f.colour + b.colour);
      }
      t.rgba[size_t(i) * kSize + size_t(j)] =
          glm::vec4(glm::clamp(c, 0.0, 1.0), float(std::min(ratio * meanDepth, kOpaqueDepth)));
    }
  // What skipping reads: an entry shows if any entry within a row's spacing (and one more, the
  // interpolation's) does.
  t.occupancy = lut;
  for (int k = 0; k < entries; ++k) {
    float a = 0.0f;
    for (int d = std::max(0, k - step - 1); d <= std::min(end, k + step + 1); ++d)
      a = std::max(a, lut.rgba[size_t(d)].a);
    t.occupancy.rgba[size_t(k)].a = a;
  }
  return t;
}

}  // namespace voxray
