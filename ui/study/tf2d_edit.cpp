#include "tf2d_edit.h"

#include <algorithm>
#include <cmath>

namespace voxray {

bool tf2dContains(const Tf2dPrimitive& p, double hu, double g) {
  if (g < p.g0 || g > p.g1 || hu < p.hu0 || hu > p.hu1) return false;
  if (p.shape == Tf2dShape::Rectangle) return true;
  // The triangle's half-width grows from 0 at |gradient| 0 to half the HU span at g1.
  double half = 0.5 * (p.hu1 - p.hu0) * (p.g1 > 0.0 ? g / p.g1 : 1.0);
  return std::abs(hu - 0.5 * (p.hu0 + p.hu1)) <= half;
}

std::optional<Tf2dHit> tf2dHitTest(const Tf2d& tf, double hu, double g, double huTol, double gTol) {
  const auto& ps = tf.primitives;
  for (size_t k = ps.size(); k-- > 0;) {
    const Tf2dPrimitive& p = ps[k];
    const std::pair<Tf2dPart, glm::dvec2> corners[] = {{Tf2dPart::LowHuLowG, {p.hu0, p.g0}},
                                                       {Tf2dPart::HighHuLowG, {p.hu1, p.g0}},
                                                       {Tf2dPart::LowHuHighG, {p.hu0, p.g1}},
                                                       {Tf2dPart::HighHuHighG, {p.hu1, p.g1}}};
    for (const auto& [part, c] : corners)
      if (std::abs(hu - c.x) <= huTol && std::abs(g - c.y) <= gTol) return Tf2dHit{k, part};
  }
  for (size_t k = ps.size(); k-- > 0;)
    if (tf2dContains(ps[k], hu, g)) return Tf2dHit{k, Tf2dPart::Body};
  return std::nullopt;
}

Tf2dPrimitive tf2dMoved(Tf2dPrimitive p, double dHu, double dG) {
  dG = std::max(dG, -p.g0);
  p.hu0 += dHu;
  p.hu1 += dHu;
  p.g0 += dG;
  p.g1 += dG;
  return p;
}

Tf2dPrimitive tf2dResized(Tf2dPrimitive p, Tf2dPart part, double hu, double g) {
  bool lowHu = part == Tf2dPart::LowHuLowG || part == Tf2dPart::LowHuHighG;
  bool lowG = part == Tf2dPart::LowHuLowG || part == Tf2dPart::HighHuLowG;
  if (part == Tf2dPart::Body) return p;
  if (lowHu)
    p.hu0 = std::min(hu, p.hu1 - kTf2dMinHu);
  else
    p.hu1 = std::max(hu, p.hu0 + kTf2dMinHu);
  if (lowG)
    p.g0 = std::max(0.0, std::min(g, p.g1 - kTf2dMinG));
  else
    p.g1 = std::max(g, p.g0 + kTf2dMinG);
  return p;
}

}  // namespace voxray
