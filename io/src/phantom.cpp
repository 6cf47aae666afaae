#include "voxray/io/phantom.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/component_wise.hpp>

#include "voxray/io/error.h"
#include "voxray/io/parallel.h"

namespace voxray {
namespace {

// Coordinates are LPS in units of the half box (128 mm): x = left, y = posterior, z = up.
constexpr double kHalfBoxMm = 128.0;
constexpr double kAir = -1000.0;

struct Ellipsoid {
  glm::dvec3 centre;
  glm::dvec3 semiAxes;
  double angleZDeg;  // rotation about z, for the tilted ventricles
  double hu;
};

// Painted in order; each one replaces what lies inside it.
const Ellipsoid kShapes[] = {
    {{0.00, 0.03, 0.02}, {0.60, 0.76, 0.84}, 0, 40},       // scalp and soft tissue
    {{0.00, -0.74, -0.14}, {0.07, 0.11, 0.15}, 0, 40},     // nose: marks anterior (-y)
    {{0.00, 0.03, 0.04}, {0.55, 0.71, 0.79}, 0, 1150},     // skull
    {{0.00, 0.03, 0.05}, {0.50, 0.66, 0.74}, 0, 42},       // grey matter
    {{0.00, 0.05, 0.08}, {0.38, 0.52, 0.55}, 0, 32},       // white matter
    {{0.10, -0.02, 0.12}, {0.05, 0.22, 0.09}, -15, 5},     // left lateral ventricle (CSF)
    {{-0.10, -0.02, 0.12}, {0.05, 0.22, 0.09}, 15, 5},     // right lateral ventricle
    {{0.22, -0.56, -0.18}, {0.075, 0.075, 0.07}, 0, 10},   // left eye, through the orbit
    {{-0.22, -0.56, -0.18}, {0.075, 0.075, 0.07}, 0, 10},  // right eye
    {{0.00, 0.20, 0.02}, {0.02, 0.02, 0.02}, 0, 300},      // calcified pineal gland
    {{0.20, 0.35, -0.15}, {0.04, 0.06, 0.05}, 0, 15},      // old infarct, left posterior
    {{0.25, -0.20, 0.30}, {0.07, 0.07, 0.07}, 0, 85},      // enhancing lesion, LEFT
};
constexpr int kLeftLesion = 11;

// The x interval where the line (., y, z) lies inside e; false if it misses.
bool rowSpan(const Ellipsoid& e, double y, double z, double& x0, double& x1) {
  const double a = glm::radians(e.angleZDeg), c = std::cos(a), s = std::sin(a);
  // q(x) = |M (p - centre)|^2 with M = diag(1/semi) * R^T: a quadratic in x.
  const glm::dvec3 d{-e.centre.x, y - e.centre.y, z - e.centre.z};
  const glm::dvec3 u = glm::dvec3(c, -s, 0) / e.semiAxes;
  const glm::dvec3 w = glm::dvec3(c * d.x + s * d.y, -s * d.x + c * d.y, d.z) / e.semiAxes;
  const double qa = glm::dot(u, u), qb = 2 * glm::dot(u, w), qc = glm::dot(w, w) - 1;
  const double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return false;
  const double root = std::sqrt(disc);
  x0 = (-qb - root) / (2 * qa);
  x1 = (-qb + root) / (2 * qa);
  return true;
}

// Signed distance to e's surface (half-box units), first order: (q - 1) / |grad q|.
double signedDistance(const Ellipsoid& e, const glm::dvec3& p) {
  const double a = glm::radians(e.angleZDeg), c = std::cos(a), s = std::sin(a);
  const glm::dvec3 d = p - e.centre;
  const glm::dvec3 r(c * d.x + s * d.y, -s * d.x + c * d.y, d.z);  // into the ellipsoid frame
  const glm::dvec3 m = r / (e.semiAxes * e.semiAxes);
  const double q = glm::dot(r / e.semiAxes, r / e.semiAxes);
  const double g = 2.0 * glm::length(m);
  return g > 0.0 ? (q - 1.0) / g : -glm::compMin(e.semiAxes);
}

}  // namespace

PhantomLesion headPhantomLeftLesion() {
  const Ellipsoid& e = kShapes[kLeftLesion];
  return {e.centre * kHalfBoxMm, e.semiAxes.x * kHalfBoxMm, e.hu};
}

Volume makeHeadPhantom(int size) {
  if (size < 2 || size > 1024) {
    throw inputError("phantom size " + std::to_string(size) + " must be between 2 and 1024");
  }
  Volume v;
  v.dims = glm::ivec3(size);
  v.spacingMm = glm::dvec3(2 * kHalfBoxMm / size);
  v.originMm = glm::dvec3(-(size - 1) * 0.5 * v.spacingMm.x);  // centre of the box at 0
  v.sourceType = "phantom";
  v.modality = "CT";  // a CT-like head in HU: it opens with the CT default window
  v.unit = "HU";
  v.voxels.assign(v.voxelCount(), int16_t(kAir));

  // Voxel i has its centre at (i + 0.5 - half) / half in half-box units.
  const double half = size * 0.5;
  const auto toUnits = [&](int i) { return (i + 0.5 - half) / half; };
  // Edges are blurred over three voxels (partial volume and the scanner's point spread),
  // so iso surfaces and gradients are smooth instead of terraced.
  parallelFor(size_t(size), [&](size_t slice) {
    const int k = int(slice);
    std::vector<double> row(static_cast<size_t>(size));
    for (int j = 0; j < size; ++j) {
      std::fill(row.begin(), row.end(), kAir);
      for (const Ellipsoid& e : kShapes) {
        // The span of the ellipsoid grown by two voxels: everything it can touch.
        Ellipsoid grown = e;
        grown.semiAxes += 2.0 / half;
        double x0, x1;
        if (!rowSpan(grown, toUnits(j), toUnits(k), x0, x1)) continue;
        const int first = std::max(0, int(std::floor(x0 * half + half - 0.5)));
        const int last = std::min(size - 1, int(std::ceil(x1 * half + half - 0.5)));
        for (int i = first; i <= last; ++i) {
          double d = signedDistance(e, {toUnits(i), toUnits(j), toUnits(k)}) * half;
          double t = std::clamp(0.5 - d / 3.0, 0.0, 1.0);
          double coverage = t * t * (3.0 - 2.0 * t);  // smoothstep across +-1.5 voxels
          row[size_t(i)] += (e.hu - row[size_t(i)]) * coverage;
        }
      }
      int16_t* out = v.voxels.data() + v.index(0, j, k);
      for (int i = 0; i < size; ++i) out[i] = int16_t(std::lround(row[size_t(i)]));
    }
  });
  return v;
}

}  // namespace voxray
