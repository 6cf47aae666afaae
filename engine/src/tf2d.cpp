#include "voxray/engine/tf2d.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "text_parse.h"
#include "tf2d_table.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

constexpr int kColumns = VOXRAY_TF2D_VALUES;
constexpr int kRows = VOXRAY_TF2D_GRADIENTS;

// Shortest text that reads back as the same double (sessions and flags round-trip exactly).
std::string exact(double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// 1 inside the core, falling linearly to 0 at the border over the outer SOFT fraction; D is
// the distance from the middle in half-extents.
double ramp(double d, double soft) {
  if (!(d <= 1.0)) return 0.0;
  if (soft > 0.0 && d > 1.0 - soft) return (1.0 - d) / soft;
  return 1.0;
}

const char* shapeName(Tf2dShape s) { return s == Tf2dShape::Triangle ? "tri" : "rect"; }

}  // namespace

void validate(const Tf2d& tf, const std::string& origin) {
  auto fail = [&](const std::string& what) { throw inputError(origin + ": " + what); };
  if (tf.primitives.size() > kMaxTf2dPrimitives)
    fail("tf2d has " + std::to_string(tf.primitives.size()) + " primitives; at most " +
         std::to_string(kMaxTf2dPrimitives) + " are read");
  if (!std::isfinite(tf.gradientMax) || tf.gradientMax < 0.0)
    fail("tf2d gradientMax is " + exact(tf.gradientMax) +
         "; it must be a gradient magnitude in HU/mm, 0 or more (0: the highest g1)");
  for (size_t i = 0; i < tf.primitives.size(); ++i) {
    const Tf2dPrimitive& p = tf.primitives[i];
    std::string at = "tf2d primitive " + std::to_string(i + 1) + " (" + shapeName(p.shape) + "): ";
    const std::pair<const char*, double> fields[] = {
        {"hu0", p.hu0},    {"hu1", p.hu1},         {"g0", p.g0},
        {"g1", p.g1},      {"red", p.rgb.r},       {"green", p.rgb.g},
        {"blue", p.rgb.b}, {"opacity", p.opacity}, {"soft", p.soft}};
    for (const auto& [name, v] : fields)
      if (!std::isfinite(v)) fail(at + name + " is not a finite number");
    if (!(p.hu1 > p.hu0))
      fail(at + "hu1 (" + exact(p.hu1) + ") must be above hu0 (" + exact(p.hu0) +
           "): the shape has no width");
    if (p.g0 < 0.0) fail(at + "g0 is " + exact(p.g0) + "; a gradient magnitude is 0 or more");
    if (!(p.g1 > p.g0))
      fail(at + "g1 (" + exact(p.g1) + ") must be above g0 (" + exact(p.g0) +
           "): the shape has no height");
    for (int k = 4; k < 9; ++k)
      if (!(fields[k].second >= 0.0 && fields[k].second <= 1.0))
        fail(at + fields[k].first + " is " + exact(fields[k].second) + "; it must lie in 0 ... 1");
  }
}

double primitiveOpacity(const Tf2dPrimitive& p, double hu, double g) {
  if (!(g >= p.g0 && g <= p.g1)) return 0.0;
  double middle = 0.5 * (p.hu0 + p.hu1), half = 0.5 * (p.hu1 - p.hu0);
  if (p.shape == Tf2dShape::Triangle) half *= g / p.g1;
  if (!(half > 0.0)) return 0.0;
  double gHalf = 0.5 * (p.g1 - p.g0);
  double dv = std::abs(hu - middle) / half;
  double dg = std::abs(g - 0.5 * (p.g0 + p.g1)) / gHalf;
  return p.opacity * ramp(dv, p.soft) * ramp(dg, p.soft);
}

glm::dvec4 tf2dAt(const Tf2d& tf, double hu, double g) {
  double clear = 1.0, sum = 0.0;
  glm::dvec3 rgb(0.0);
  for (const Tf2dPrimitive& p : tf.primitives) {
    double a = primitiveOpacity(p, hu, g);
    if (a <= 0.0) continue;
    clear *= 1.0 - a;
    sum += a;
    rgb += a * p.rgb;
  }
  if (sum <= 0.0) return glm::dvec4(0.0);
  return glm::dvec4(rgb / sum, 1.0 - clear);
}

double tf2dGradientMax(const Tf2d& tf) {
  if (tf.gradientMax > 0.0) return tf.gradientMax;
  double top = 0.0;
  for (const Tf2dPrimitive& p : tf.primitives) top = std::max(top, p.g1);
  return top > 0.0 ? top : 1.0;
}

int Tf2dTable::columns() const { return kColumns; }
int Tf2dTable::rows() const { return kRows; }

glm::dvec4 Tf2dTable::lookup(double stored, double storedPerMm) const {
  if (rgba.empty()) return glm::dvec4(0.0);
  double x = std::clamp((stored - storedLo) * perStored, 0.0, double(kColumns - 1));
  double y = std::min(storedPerMm * perStoredPerMm, double(kRows - 1));
  double x0 = std::floor(x), y0 = std::floor(y);
  int i = int(x0), j = int(y0);
  int i1 = std::min(i + 1, kColumns - 1), j1 = std::min(j + 1, kRows - 1);
  double fx = x - x0, fy = y - y0;
  auto at = [&](int r, int c) { return glm::dvec4(rgba[size_t(r) * kColumns + size_t(c)]); };
  glm::dvec4 a = glm::mix(at(j, i), at(j, i1), fx);
  glm::dvec4 b = glm::mix(at(j1, i), at(j1, i1), fx);
  return glm::mix(a, b, fy);
}

Tf2dTable bakeTf2dTable(const Tf2d& tf, const Volume& v) {
  Tf2dTable t;
  if (tf.empty()) return t;
  double lo = tf.primitives.front().hu0, hi = tf.primitives.front().hu1;
  for (const Tf2dPrimitive& p : tf.primitives) lo = std::min(lo, p.hu0), hi = std::max(hi, p.hu1);
  // Columns 1 ... columns - 2 span [lo, hi]; the first and last stay empty (every shape is 0
  // outside its extent), so the clamped lookup reads 0 beyond it.
  double huStep = (hi - lo) / double(kColumns - 3);
  double huLo = lo - huStep;
  double gMax = tf2dGradientMax(tf);
  double slope = v.slope != 0.0 ? v.slope : 1.0;
  t.storedLo = v.toStored(huLo);
  t.perStored = slope / huStep;  // negative with a negative slope: columns still run along HU
  t.perStoredPerMm = double(kRows - 1) * std::abs(slope) / gMax;
  t.rgba.resize(size_t(kColumns) * kRows);
  for (int j = 0; j < kRows; ++j) {
    double g = gMax * double(j) / double(kRows - 1);
    for (int i = 0; i < kColumns; ++i)
      t.rgba[size_t(j) * kColumns + size_t(i)] =
          glm::vec4(glm::clamp(tf2dAt(tf, huLo + huStep * double(i), g), 0.0, 1.0));
  }
  return t;
}

void reduceTf2dToLut(const Tf2dTable& table, Lut& lut) {
  if (table.empty()) return;
  // Each column's largest opacity over every row, and the colour there.
  std::vector<glm::vec4> best(size_t(kColumns), glm::vec4(0.0f));
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      const glm::vec4& e = table.rgba[size_t(j) * kColumns + size_t(i)];
      if (e.a > best[size_t(i)].a) best[size_t(i)] = e;
    }
  auto column = [&](double stored) { return (stored - table.storedLo) * table.perStored; };
  const size_t n = lut.rgba.size();
  for (size_t k = 0; k < n; ++k) {
    // Entry k weighs into lookups between entries k - 1 and k + 1; the 2D lookups there read
    // columns floor(x) ... floor(x) + 1; a hundredth of a column either side absorbs the
    // kernels' float rounding of x (about 1e-3 columns at CT values).
    double s0 = lut.storedMin + (double(k) - 1.0) / lut.scale;
    double s1 = lut.storedMin + (double(k) + 1.0) / lut.scale;
    double c0 = column(s0), c1 = column(s1);
    if (c0 > c1) std::swap(c0, c1);
    int a = int(std::clamp(std::floor(c0 - 0.01), 0.0, double(kColumns - 1)));
    int b = int(std::clamp(std::floor(c1 + 0.01) + 1.0, 0.0, double(kColumns - 1)));
    glm::vec4 e(0.0f);
    for (int i = a; i <= b; ++i)
      if (best[size_t(i)].a > e.a) e = best[size_t(i)];
    lut.rgba[k] = e;
  }
}

Tf2d parseTf2d(const std::string& text) {
  Tf2d tf;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ';')) {
    if (item.empty()) continue;
    size_t colon = item.find(':');
    std::string kind = item.substr(0, colon);
    std::string rest = colon == std::string::npos ? "" : item.substr(colon + 1);
    if (kind == "gmax") {
      tf.gradientMax = text::toDouble("tf2d", rest);
      continue;
    }
    if (kind != "rect" && kind != "tri")
      throw inputError("--tf2d: '" + item +
                       "' is not a shape; give rect:HU0,HU1,G0,G1,R,G,B,A[,SOFT], "
                       "tri:HU0,HU1,G0,G1,R,G,B,A[,SOFT] or gmax:G, separated by ';'");
    if (tf.primitives.size() >= kMaxTf2dPrimitives)
      throw inputError("--tf2d: more than " + std::to_string(kMaxTf2dPrimitives) +
                       " primitives; at most " + std::to_string(kMaxTf2dPrimitives) + " are read");
    // Each number by the field it is, so a typo names it (text::toDouble would not).
    static const char* const kFields[] = {"hu0",   "hu1",  "g0",      "g1",  "red",
                                          "green", "blue", "opacity", "soft"};
    std::vector<double> v;
    std::istringstream numbers(rest);
    std::string field;
    while (std::getline(numbers, field, ',')) {
      if (v.size() == 9) break;
      double x = 0.0;
      auto r = std::from_chars(field.data(), field.data() + field.size(), x);
      if (r.ec != std::errc() || r.ptr != field.data() + field.size() || !std::isfinite(x))
        throw inputError("--tf2d: '" + item + "': " + kFields[v.size()] + " is '" + field +
                         "', not a finite number");
      v.push_back(x);
    }
    if (v.size() < 8 || std::getline(numbers, field, ','))
      throw inputError("--tf2d: '" + item +
                       "' must have 8 or 9 numbers: HU0,HU1,G0,G1,R,G,B,A[,SOFT]");
    Tf2dPrimitive p;
    p.shape = kind == "tri" ? Tf2dShape::Triangle : Tf2dShape::Rectangle;
    p.hu0 = v[0], p.hu1 = v[1], p.g0 = v[2], p.g1 = v[3];
    p.rgb = {v[4], v[5], v[6]};
    p.opacity = v[7];
    p.soft = v.size() > 8 ? v[8] : 0.0;
    tf.primitives.push_back(p);
  }
  validate(tf, "--tf2d");
  return tf;
}

std::string formatTf2d(const Tf2d& tf) {
  std::string out;
  for (const Tf2dPrimitive& p : tf.primitives) {
    if (!out.empty()) out += ';';
    out += shapeName(p.shape);
    out += ':';
    const double v[] = {p.hu0, p.hu1, p.g0, p.g1, p.rgb.r, p.rgb.g, p.rgb.b, p.opacity, p.soft};
    for (size_t k = 0; k < 9; ++k) {
      if (k) out += ',';
      out += exact(v[k]);
    }
  }
  if (tf.gradientMax > 0.0) {
    if (!out.empty()) out += ';';
    out += "gmax:";
    out += exact(tf.gradientMax);
  }
  return out;
}

}  // namespace voxray
