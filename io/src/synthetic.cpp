#include "voxray/io/synthetic.h"

#include <algorithm>
#include <cmath>

#include "voxray/io/error.h"

namespace voxray {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFm = 6.0, kAlpha = 0.25;  // Marschner and Lobb's standard parameters
constexpr double kHuPerVoxel = 100.0;       // distance fields: value per voxel of distance

glm::dvec3 centre(const SyntheticSpec& s) { return glm::dvec3(0.5 * (s.size - 1)); }

// Marschner-Lobb on [-1, 1]^3 with u = -1 + 2 i / (n - 1): 41 samples span it exactly.
double mlRho(const glm::dvec3& u) {
  double r = std::sqrt(u.x * u.x + u.y * u.y);
  double rr = std::cos(2.0 * kPi * kFm * std::cos(0.5 * kPi * r));
  return (1.0 - std::sin(0.5 * kPi * u.z) + kAlpha * (1.0 + rr)) / (2.0 * (1.0 + kAlpha));
}

glm::dvec3 mlRhoGradient(const glm::dvec3& u) {
  double r = std::sqrt(u.x * u.x + u.y * u.y);
  double k = 1.0 / (2.0 * (1.0 + kAlpha));
  double dz = -0.5 * kPi * std::cos(0.5 * kPi * u.z) * k;
  // d rho_r / dr divided by r stays finite at r = 0 (sin(pi r / 2) / r -> pi / 2).
  double sinc = r > 1e-12 ? std::sin(0.5 * kPi * r) / r : 0.5 * kPi;
  double drOverR =
      std::sin(2.0 * kPi * kFm * std::cos(0.5 * kPi * r)) * 2.0 * kPi * kFm * 0.5 * kPi * sinc;
  return glm::dvec3(kAlpha * drOverR * u.x * k, kAlpha * drOverR * u.y * k, dz);
}

double storedMaxAbs(const SyntheticSpec& s) {
  if (s.shape == SyntheticShape::MarschnerLobb) return 1000.0;
  return kHuPerVoxel * 0.5 * std::sqrt(3.0) * s.size;  // no distance in the box exceeds it
}

}  // namespace

double AnalyticField::value(const glm::dvec3& p) const {
  glm::dvec3 q = p - centre(spec);
  double n1 = double(spec.size - 1);
  switch (spec.shape) {
    case SyntheticShape::MarschnerLobb:
      return 2000.0 * mlRho(q * (2.0 / n1)) - 1000.0;
    case SyntheticShape::Sphere:
      return kHuPerVoxel * (0.35 * n1 - glm::length(q));
    case SyntheticShape::Torus: {
      double ring = std::sqrt(q.x * q.x + q.y * q.y) - 0.3 * n1;
      return kHuPerVoxel * (0.12 * n1 - std::sqrt(ring * ring + q.z * q.z));
    }
    case SyntheticShape::RampX:
      return kHuPerVoxel * q.x;
  }
  return 0.0;
}

glm::dvec3 AnalyticField::gradient(const glm::dvec3& p) const {
  glm::dvec3 q = p - centre(spec);
  double n1 = double(spec.size - 1);
  switch (spec.shape) {
    case SyntheticShape::MarschnerLobb:
      return 2000.0 * (2.0 / n1) * mlRhoGradient(q * (2.0 / n1));
    case SyntheticShape::Sphere: {
      double d = glm::length(q);
      return d > 0.0 ? -kHuPerVoxel * q / d : glm::dvec3(0.0);
    }
    case SyntheticShape::Torus: {
      double rxy = std::sqrt(q.x * q.x + q.y * q.y);
      double ring = rxy - 0.3 * n1;
      double d = std::sqrt(ring * ring + q.z * q.z);
      if (d == 0.0 || rxy == 0.0) return glm::dvec3(0.0);
      return -kHuPerVoxel / d * glm::dvec3(ring * q.x / rxy, ring * q.y / rxy, q.z);
    }
    case SyntheticShape::RampX:
      return glm::dvec3(kHuPerVoxel, 0.0, 0.0);
  }
  return glm::dvec3(0.0);
}

double AnalyticField::surfaceDistance(const glm::dvec3& p) const {
  if (spec.shape != SyntheticShape::MarschnerLobb) return std::abs(value(p)) / kHuPerVoxel;
  // Newton steps along the gradient land on the nearby surface; measured from the start.
  glm::dvec3 x = p;
  for (int i = 0; i < 12; ++i) {
    glm::dvec3 g = gradient(x);
    double gg = glm::dot(g, g);
    if (!(gg > 0.0)) break;
    glm::dvec3 dx = value(x) / gg * g;
    x -= dx;
    if (glm::length(dx) < 1e-12) break;
  }
  return glm::length(x - p);
}

Volume makeSyntheticVolume(const SyntheticSpec& spec) {
  if (spec.size < 2 || spec.size > 1024)
    throw inputError("synthetic volume: size " + std::to_string(spec.size) +
                     " is outside 2..1024 voxels");
  Volume v;
  v.dims = glm::ivec3(spec.size);
  v.spacingMm = glm::dvec3(1.0);
  v.originMm = -centre(spec);
  v.sourceType = std::string("synthetic ") + toString(spec.shape);
  v.unit = "value";  // test shapes, not HU: they open with a look from their own values
  // A power-of-two slope: the ramp's values (multiples of 50) stay exact.
  v.slope = std::ldexp(1.0, int(std::ceil(std::log2(storedMaxAbs(spec) / 32000.0))));
  v.voxels.resize(v.voxelCount());
  AnalyticField f{spec};
  for (int z = 0; z < spec.size; ++z)
    for (int y = 0; y < spec.size; ++y)
      for (int x = 0; x < spec.size; ++x) {
        double s = std::nearbyint(f.value(glm::dvec3(x, y, z)) / v.slope);
        v.voxels[v.index(x, y, z)] = int16_t(std::clamp(s, -32768.0, 32767.0));
      }
  return v;
}

SyntheticShape parseSyntheticShape(const std::string& s) {
  if (s == "ml" || s == "marschner-lobb") return SyntheticShape::MarschnerLobb;
  if (s == "sphere") return SyntheticShape::Sphere;
  if (s == "torus") return SyntheticShape::Torus;
  if (s == "ramp") return SyntheticShape::RampX;
  throw inputError("unknown synthetic volume '" + s + "': use ml, sphere, torus or ramp");
}

const char* toString(SyntheticShape s) {
  switch (s) {
    case SyntheticShape::MarschnerLobb:
      return "ml";
    case SyntheticShape::Sphere:
      return "sphere";
    case SyntheticShape::Torus:
      return "torus";
    case SyntheticShape::RampX:
      return "ramp";
  }
  return "?";
}

}  // namespace voxray
