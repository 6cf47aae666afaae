#include "mpr_planes.h"

#include <algorithm>
#include <cmath>

#include "voxray/io/volume.h"

namespace voxray {

namespace {
constexpr double kLetterThreshold = 0.2;
}

PlaneFrame baseFrame(const glm::dmat3& direction, const SliceAxes& a) {
  return {direction[a.uAxis] * (a.uFlip ? -1.0 : 1.0), direction[a.vAxis] * (a.vFlip ? -1.0 : 1.0),
          direction[a.nAxis]};
}

PlaneFrame rotateFrame(const glm::dmat3& r, const PlaneFrame& f) {
  return {r * f.right, r * f.down, r * f.normal};
}

glm::dmat3 rotationAbout(const glm::dvec3& axis, double angle) {
  // Rodrigues: R = I cos + (1 - cos) a a^T + sin [a]x, written column by column.
  const glm::dvec3 a = glm::normalize(axis);
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  return glm::dmat3(
      glm::dvec3(c + t * a.x * a.x, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y),
      glm::dvec3(t * a.x * a.y - s * a.z, c + t * a.y * a.y, t * a.y * a.z + s * a.x),
      glm::dvec3(t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, c + t * a.z * a.z));
}

glm::dmat3 rotationBetween(const glm::dvec3& from, const glm::dvec3& to) {
  const glm::dvec3 f = glm::normalize(from), t = glm::normalize(to);
  const glm::dvec3 axis = glm::cross(f, t);
  const double s = glm::length(axis), c = glm::dot(f, t);
  if (s > 1e-12) return rotationAbout(axis / s, std::atan2(s, c));
  if (c > 0) return glm::dmat3(1.0);
  // Opposite: half a turn about any axis square to FROM.
  const glm::dvec3 other = std::abs(f.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  return rotationAbout(glm::normalize(glm::cross(f, other)), M_PI);
}

glm::dmat3 orthonormalised(const glm::dmat3& m) {
  const glm::dvec3 x = glm::normalize(m[0]);
  const glm::dvec3 y = glm::normalize(m[1] - glm::dot(m[1], x) * x);
  return glm::dmat3(x, y, glm::cross(x, y));
}

bool isIdentity(const glm::dmat3& m) { return m == glm::dmat3(1.0); }

ObliqueView viewForNormal(const glm::dmat3& direction, const glm::dvec3& normal) {
  const glm::dvec3 n = glm::normalize(normal);
  ObliqueView best;
  double bestDot = -1.0;
  for (Orientation o : {Orientation::Axial, Orientation::Coronal, Orientation::Sagittal}) {
    const glm::dvec3 base = baseFrame(direction, sliceAxes(direction, o)).normal;
    const double d = glm::dot(base, n);
    if (std::abs(d) > bestDot + 1e-12) {
      bestDot = std::abs(d);
      // The normal's sign only says which side faces the viewer: keep the view's own.
      best = {o, rotationBetween(base, d < 0 ? -n : n)};
    }
  }
  return best;
}

glm::dvec3 patientMmToVoxel(const Volume& v, const glm::dvec3& mm) {
  return glm::inverse(v.direction) * (mm - v.originMm) / v.spacingMm;
}

glm::dvec2 traceOnScreen(const PlaneFrame& f, const glm::dvec3& otherNormal) {
  const glm::dvec3 line = glm::cross(f.normal, otherNormal);
  const glm::dvec2 s(glm::dot(line, f.right), glm::dot(line, f.down));
  const double n = glm::length(s);
  return n < 1e-9 ? glm::dvec2(0.0) : s / n;
}

std::vector<glm::dvec3> planeInBox(const Volume& v, const glm::dvec3& centreVoxel,
                                   const glm::dvec3& normal) {
  if (v.voxelCount() == 0) return {};
  // A square in the plane larger than the box, clipped by the box's six faces
  // (Sutherland-Hodgman), all in voxel coordinates.
  const glm::dmat3 toVoxel = glm::inverse(
      v.direction * glm::dmat3(glm::dvec3(v.spacingMm.x, 0, 0), glm::dvec3(0, v.spacingMm.y, 0),
                               glm::dvec3(0, 0, v.spacingMm.z)));
  const glm::dvec3 n = glm::normalize(normal);
  const glm::dvec3 a = glm::normalize(
      glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
  const glm::dvec3 b = glm::cross(n, a);
  const double r = 2.0 * glm::length(v.extentMm());
  const glm::dvec3 centreMm = v.direction * (centreVoxel * v.spacingMm);
  std::vector<glm::dvec3> poly;
  for (const glm::dvec2 c :
       {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
    poly.push_back(toVoxel * (centreMm + r * (c.x * a + c.y * b)));
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const double bound = side == 0 ? -0.5 : v.dims[axis] - 0.5;
      auto inside = [&](const glm::dvec3& p) {
        return side == 0 ? p[axis] >= bound : p[axis] <= bound;
      };
      std::vector<glm::dvec3> next;
      for (size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec3 p = poly[i], q = poly[(i + 1) % poly.size()];
        if (inside(p)) next.push_back(p);
        if (inside(p) != inside(q))
          next.push_back(p + (q - p) * ((bound - p[axis]) / (q[axis] - p[axis])));
      }
      poly = std::move(next);
      if (poly.empty()) return {};
    }
  return poly;
}

std::string patientLetters(const glm::dvec3& dir) {
  static constexpr char kPositive[] = "LPS", kNegative[] = "RAI";
  std::array<int, 3> order{0, 1, 2};
  // Strength rounded to 1e-6 so that equal components (a 45 degree plane) keep the order
  // L/R, P/A, S/I whatever the last bits of the rotation.
  auto strength = [&](int axis) { return std::round(std::abs(dir[axis]) * 1e6); };
  std::stable_sort(order.begin(), order.end(),
                   [&](int x, int y) { return strength(x) > strength(y); });
  std::string letters;
  for (int axis : order)
    if (std::abs(dir[axis]) >= kLetterThreshold)
      letters += dir[axis] > 0 ? kPositive[axis] : kNegative[axis];
  return letters;
}

std::array<std::string, 4> frameLabels(const PlaneFrame& f) {
  return {patientLetters(-f.right), patientLetters(f.right), patientLetters(-f.down),
          patientLetters(f.down)};
}

}  // namespace voxray
