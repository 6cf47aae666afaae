#include "voxray/engine/volume_property.h"

#include <algorithm>
#include <cmath>

#include "frame_setup.h"
#include "monotone_curve.h"
#include "voxray/engine/render_params.h"
#include "voxray/io/error.h"

namespace voxray {

namespace {

std::string numberText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void checkList(const std::string& origin, const std::string& field, size_t count, bool mayBeEmpty) {
  if (count == 0 && !mayBeEmpty)
    throw inputError(origin + ": " + field + " has no points; give at least one");
  if (count > kMaxTfPoints)
    throw inputError(origin + ": " + field + " has " + std::to_string(count) + " points; at most " +
                     std::to_string(kMaxTfPoints) + " are read");
}

void checkUnit(const std::string& origin, const std::string& field, size_t index, double v) {
  if (!std::isfinite(v) || v < 0.0 || v > 1.0)
    throw inputError(origin + ": " + field + " point " + std::to_string(index + 1) + " has " +
                     numberText(v) + "; it must lie in 0 ... 1");
}

void checkPosition(const std::string& origin, const std::string& field, size_t index, double x,
                   const double* previous) {
  if (!std::isfinite(x))
    throw inputError(origin + ": " + field + " point " + std::to_string(index + 1) +
                     " is at a position that is not a finite number");
  if (previous && x < *previous)
    throw inputError(origin + ": " + field + " point " + std::to_string(index + 1) + " (at " +
                     numberText(x) + ") comes after one at " + numberText(*previous) +
                     "; points must be sorted by position");
}

template <class Node, class X, class Values>
void checkNodes(const std::string& origin, const std::string& field, const std::vector<Node>& nodes,
                bool mayBeEmpty, X x, Values values) {
  checkList(origin, field, nodes.size(), mayBeEmpty);
  for (size_t i = 0; i < nodes.size(); ++i) {
    double here = x(nodes[i]);
    double before = i ? x(nodes[i - 1]) : 0.0;
    checkPosition(origin, field, i, here, i ? &before : nullptr);
    for (double v : values(nodes[i])) checkUnit(origin, field, i, v);
  }
}

MonotoneCurve opacityCurve(const std::vector<OpacityNode>& nodes, TfCurve curve) {
  std::vector<double> x, y;
  for (const auto& n : nodes) {
    x.push_back(n.x);
    y.push_back(n.opacity);
  }
  return MonotoneCurve(std::move(x), std::move(y), curve == TfCurve::Smooth);
}

MonotoneCurve colorCurve(const std::vector<ColorNode>& nodes, int channel, TfCurve curve) {
  std::vector<double> x, y;
  for (const auto& n : nodes) {
    x.push_back(n.hu);
    y.push_back(n.rgb[channel]);
  }
  return MonotoneCurve(std::move(x), std::move(y), curve == TfCurve::Smooth);
}

// The four curves of a property's render table, made once.
struct TableCurves {
  MonotoneCurve r, g, b, a;
  explicit TableCurves(const VolumeProperty& vp)
      : r(colorCurve(vp.color, 0, vp.curve)),
        g(colorCurve(vp.color, 1, vp.curve)),
        b(colorCurve(vp.color, 2, vp.curve)),
        a(opacityCurve(vp.opacity, vp.curve)) {}
  glm::dvec4 at(double hu) const { return {r.at(hu), g.at(hu), b.at(hu), a.at(hu)}; }
  glm::dvec4 leftOf(double hu) const {
    return {r.leftOf(hu), g.leftOf(hu), b.leftOf(hu), a.leftOf(hu)};
  }
};

// Straight lines between table points may differ from a smooth curve by this much at most.
constexpr double kTableTolerance = 1.0 / 1024.0;

void addBetween(const TableCurves& c, double lo, double hi, std::vector<ControlPoint>& out,
                int depth) {
  glm::dvec4 a = c.at(lo), b = c.leftOf(hi);
  double worst = 0.0;
  for (double f : {0.25, 0.5, 0.75}) {
    glm::dvec4 chord = glm::mix(a, b, f), curve = c.at(lo + f * (hi - lo));
    for (int k = 0; k < 4; ++k) worst = std::max(worst, std::abs(curve[k] - chord[k]));
  }
  if (worst <= kTableTolerance || depth >= 12) return;
  double mid = 0.5 * (lo + hi);
  addBetween(c, lo, mid, out, depth + 1);
  out.push_back({mid, c.at(mid)});
  addBetween(c, mid, hi, out, depth + 1);
}

}  // namespace

void validate(const VolumeProperty& vp, const std::string& origin) {
  checkNodes(
      origin, "colour", vp.color, false, [](const ColorNode& n) { return n.hu; },
      [](const ColorNode& n) {
        return std::vector<double>{n.rgb.r, n.rgb.g, n.rgb.b};
      });
  checkNodes(
      origin, "opacity", vp.opacity, false, [](const OpacityNode& n) { return n.x; },
      [](const OpacityNode& n) { return std::vector<double>{n.opacity}; });
  checkNodes(
      origin, "gradient opacity", vp.gradientOpacity, true,
      [](const OpacityNode& n) { return n.x; },
      [](const OpacityNode& n) { return std::vector<double>{n.opacity}; });
  if (!std::isfinite(vp.unitDistanceMm) || vp.unitDistanceMm < 0.0)
    throw inputError(origin + ": the unit distance must be 0 (one voxel) or a length in mm, got " +
                     numberText(vp.unitDistanceMm));
  const std::pair<const char*, double> coefficients[] = {
      {"ambient", vp.ambient}, {"diffuse", vp.diffuse}, {"specular", vp.specular}};
  for (const auto& [field, v] : coefficients)
    if (!std::isfinite(v) || v < 0.0 || v > 1.0)
      throw inputError(origin + ": " + field + " is " + numberText(v) + "; it must lie in 0 ... 1");
  if (!std::isfinite(vp.specularPower) || vp.specularPower <= 0.0)
    throw inputError(origin + ": the specular power must be a positive number, got " +
                     numberText(vp.specularPower));
  validate(vp.tf2d, origin);
}

glm::dvec3 colorAt(const VolumeProperty& vp, double hu) {
  return {colorCurve(vp.color, 0, vp.curve).at(hu), colorCurve(vp.color, 1, vp.curve).at(hu),
          colorCurve(vp.color, 2, vp.curve).at(hu)};
}

double opacityAt(const VolumeProperty& vp, double hu) {
  return opacityCurve(vp.opacity, vp.curve).at(hu);
}

double gradientOpacityAt(const VolumeProperty& vp, double gradientMagnitude) {
  if (vp.gradientOpacity.empty()) return 1.0;
  return opacityCurve(vp.gradientOpacity, vp.curve).at(gradientMagnitude);
}

bool hasGradientOpacity(const VolumeProperty& vp) {
  return std::any_of(vp.gradientOpacity.begin(), vp.gradientOpacity.end(),
                     [](const OpacityNode& n) { return n.opacity < 1.0; });
}

std::vector<ControlPoint> renderTable(const VolumeProperty& vp) {
  TableCurves curves(vp);
  std::vector<double> xs;
  for (const auto& n : vp.color) xs.push_back(n.hu);
  for (const auto& n : vp.opacity) xs.push_back(n.x);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::vector<ControlPoint> out;
  for (size_t i = 0; i < xs.size(); ++i) {
    if (i > 0 && vp.curve == TfCurve::Smooth) addBetween(curves, xs[i - 1], xs[i], out, 0);
    // A step in either list: the value just below, then the value at the point.
    glm::dvec4 below = curves.leftOf(xs[i]), at = curves.at(xs[i]);
    if (i > 0 && below != at) out.push_back({xs[i], below});
    out.push_back({xs[i], at});
  }
  return out;
}

namespace {

// The render parameter's gradient opacity (linear points): the property's points, or for a
// smooth curve 64 straight pieces along it; empty where it changes nothing.
std::vector<glm::dvec2> gradientOpacityPoints(const VolumeProperty& vp) {
  std::vector<glm::dvec2> out;
  if (!hasGradientOpacity(vp)) return out;
  if (vp.curve == TfCurve::Linear || vp.gradientOpacity.size() < 2) {
    for (const OpacityNode& n : vp.gradientOpacity) out.push_back({n.x, n.opacity});
    return out;
  }
  MonotoneCurve c = opacityCurve(vp.gradientOpacity, vp.curve);
  double lo = vp.gradientOpacity.front().x, hi = vp.gradientOpacity.back().x;
  constexpr int kPieces = 64;
  for (int i = 0; i <= kPieces; ++i) {
    double x = lo + (hi - lo) * double(i) / kPieces;
    out.push_back({x, c.at(x)});
  }
  return out;
}

}  // namespace

void applyVolumeProperty(RenderParams& p, const VolumeProperty& vp) {
  p.gradientOpacity = gradientOpacityPoints(vp);
  p.tf2d = vp.tf2d;
  p.preset.clear();
  p.presetShiftHu = 0.0;
  p.transferFunction = renderTable(vp);
  p.opacityUnitMm = vp.unitDistanceMm;
  p.mode = Mode::Dvr;
  p.shading = vp.shade;
  p.interp = vp.nearest ? Interp::Nearest : Interp::Linear;
  p.light.ambient = vp.ambient;
  p.light.diffuse = vp.diffuse;
  p.light.specular = vp.specular;
  p.light.shininess = vp.specularPower;
}

VolumeProperty volumePropertyOf(const RenderParams& p) {
  VolumeProperty vp;
  vp.name = p.preset;
  for (const ControlPoint& c : frameTransferFunction(p).points) {
    vp.color.push_back({c.hu, glm::dvec3(c.rgba)});
    vp.opacity.push_back({c.hu, c.rgba.a});
  }
  for (const glm::dvec2& g : p.gradientOpacity) vp.gradientOpacity.push_back({g.x, g.y});
  vp.tf2d = p.tf2d;
  vp.unitDistanceMm = p.opacityUnitMm;
  vp.shade = p.shading;
  vp.nearest = p.interp == Interp::Nearest;
  vp.ambient = p.light.ambient;
  vp.diffuse = p.light.diffuse;
  vp.specular = p.light.specular;
  vp.specularPower = p.light.shininess;
  return vp;
}

}  // namespace voxray
