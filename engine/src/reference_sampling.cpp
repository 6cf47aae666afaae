#include "reference_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "jitter_hash.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

// kernels/reconstruction/gradients.cl's GRADIENT_ZERO_REL: a gradient at most this fraction of the
// largest |voxel| its stencil read is cancellation noise in float, so both renderers call it 0.
constexpr double kGradientZeroRel = 1e-5;

// sampleVolume that also raises *largest to the largest |voxel| it read.
double sampleTracked(const Volume& v, Interp interp, const glm::dvec3& p, double* largest) {
  glm::ivec3 hi = v.dims - 1;
  auto at = [&](int x, int y, int z) {
    double s = v.at(x, y, z);
    if (largest) *largest = std::max(*largest, std::abs(s));
    return s;
  };
  if (interp == Interp::Nearest) {
    glm::ivec3 i = glm::clamp(glm::ivec3(glm::floor(p + 0.5)), glm::ivec3(0), hi);
    return at(i.x, i.y, i.z);
  }
  glm::dvec3 f0 = glm::floor(p);
  glm::dvec3 f = p - f0;
  glm::ivec3 i0(f0);
  glm::ivec3 a = glm::clamp(i0, glm::ivec3(0), hi);
  glm::ivec3 b = glm::clamp(i0 + 1, glm::ivec3(0), hi);
  auto lerp = [](double x, double y, double t) { return x + (y - x) * t; };
  double c00 = lerp(at(a.x, a.y, a.z), at(b.x, a.y, a.z), f.x);
  double c10 = lerp(at(a.x, b.y, a.z), at(b.x, b.y, a.z), f.x);
  double c01 = lerp(at(a.x, a.y, b.z), at(b.x, a.y, b.z), f.x);
  double c11 = lerp(at(a.x, b.y, b.z), at(b.x, b.y, b.z), f.x);
  return lerp(lerp(c00, c10, f.y), lerp(c01, c11, f.y), f.z);
}

glm::dvec3 zeroIfCancelled(const glm::dvec3& g, double largest) {
  double m = std::max({std::abs(g.x), std::abs(g.y), std::abs(g.z)});
  return m <= kGradientZeroRel * largest ? glm::dvec3(0.0) : g;
}

}  // namespace

double sampleVolume(const Volume& v, Interp interp, const glm::dvec3& p) {
  return sampleTracked(v, interp, p, nullptr);
}

glm::dvec3 volumeGradient(const Volume& v, Interp interp, Gradient op, const glm::dvec3& p) {
  double largest = 0.0;
  auto s = [&](double dx, double dy, double dz) {
    return sampleTracked(v, interp, p + glm::dvec3(dx, dy, dz), &largest);
  };
  if (op == Gradient::Central) {
    glm::dvec3 g(s(1, 0, 0) - s(-1, 0, 0), s(0, 1, 0) - s(0, -1, 0), s(0, 0, 1) - s(0, 0, -1));
    return zeroIfCancelled(0.5 * g, largest);
  }
  // Cross-axis weights by the number of non-zero cross offsets (0, 1, 2).
  const double sobel[3] = {6.0, 3.0, 1.0};
  const double zh[3] = {1.0, 1.0 / std::sqrt(2.0), 1.0 / std::sqrt(3.0)};
  const double* w = op == Gradient::Sobel ? sobel : zh;
  double sum = w[0] + 4.0 * w[1] + 4.0 * w[2];
  glm::dvec3 g(0.0);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0 && dz == 0) continue;
        double val = s(dx, dy, dz);
        g.x += val * dx * w[std::abs(dy) + std::abs(dz)];
        g.y += val * dy * w[std::abs(dx) + std::abs(dz)];
        g.z += val * dz * w[std::abs(dx) + std::abs(dy)];
      }
  return zeroIfCancelled(g * (0.5 / sum), largest);
}

int gradientSamples(Gradient op) { return op == Gradient::Central ? 6 : 26; }

float jitterFraction(int px, int py) {
  // uint32_t arithmetic wraps exactly like OpenCL's uint.
  return float(VOXRAY_JITTER_HASH(uint32_t(px), uint32_t(py))) / VOXRAY_JITTER_RANGE;
}

bool pixelRay(const ViewGeometry& g, int px, int py, int width, int height, PixelRay& r) {
  g.ray(px, py, width, height, r.ow, r.dw);
  r.ov = g.toVoxel(r.ow);
  r.dv = g.dirToVoxel(r.dw);
  return intersectBox(r.ov, r.dv, g.clipLo, g.clipHi, r.t0, r.t1, r.axis);
}

glm::dvec3 safeNormalize(glm::dvec3 v, const glm::dvec3& fallback) {
  double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(m > 1e-6) || std::isinf(m)) return fallback;
  v /= m;
  return v / std::sqrt(glm::dot(v, v));
}

}  // namespace voxray
