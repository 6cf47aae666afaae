#include "tf2d_histogram.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "voxray/io/parallel.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

// |gradient| in HU/mm at voxel (x, y, z): central differences, clamped at the faces.
struct GradientAt {
  const Volume& v;
  glm::dvec3 scale;  // HU per stored unit / (2 spacing)
  explicit GradientAt(const Volume& vol)
      : v(vol), scale(std::abs(vol.slope) / (2.0 * vol.spacingMm)) {}
  double operator()(int x, int y, int z) const {
    const glm::ivec3 d = v.dims;
    double gx = v.at(std::min(x + 1, d.x - 1), y, z) - v.at(std::max(x - 1, 0), y, z);
    double gy = v.at(x, std::min(y + 1, d.y - 1), z) - v.at(x, std::max(y - 1, 0), z);
    double gz = v.at(x, y, std::min(z + 1, d.z - 1)) - v.at(x, y, std::max(z - 1, 0));
    glm::dvec3 s2 = scale * scale;
    return std::sqrt(gx * gx * s2.x + gy * gy * s2.y + gz * gz * s2.z);
  }
};

double percentileGradient(const Volume& v, const GradientAt& grad,
                          const std::atomic<bool>* cancel) {
  // The largest |gradient| possible bounds a fine histogram (4096 bins) of the sample.
  ValueRange r = storedRange(v);
  double bound = (double(r.max) - double(r.min)) * glm::length(grad.scale) * 2.0;
  if (!(bound > 0.0)) return 1.0;
  constexpr int kFine = 4096;
  std::vector<uint64_t> fine(kFine, 0);
  std::mutex merge;
  const int zs = (v.dims.z + 3) / 4;
  parallelFor(
      size_t(zs),
      [&](size_t zi) {
        std::vector<uint64_t> local(kFine, 0);
        int z = int(zi) * 4;
        for (int y = 0; y < v.dims.y; y += 4)
          for (int x = 0; x < v.dims.x; x += 4)
            ++local[size_t(std::min(kFine - 1, int(grad(x, y, z) / bound * kFine)))];
        std::lock_guard<std::mutex> lock(merge);
        for (int k = 0; k < kFine; ++k) fine[size_t(k)] += local[size_t(k)];
      },
      cancel);
  uint64_t n = 0;
  for (uint64_t c : fine) n += c;
  uint64_t want = uint64_t(std::ceil(0.99 * double(n))), seen = 0;
  int k = 0;
  for (; k < kFine; ++k)
    if ((seen += fine[size_t(k)]) >= want) break;
  double g = (k + 1) * bound / kFine;
  return std::max(8.0, std::ceil(g / 8.0) * 8.0);
}

}  // namespace

int Tf2dHistogram::columnOf(double hu) const {
  double f = (hu - huLo) / (huHi - huLo) * kValueBins;
  return std::clamp(int(std::floor(f)), 0, kValueBins - 1);
}

int Tf2dHistogram::rowOf(double g) const {
  double f = g * (kGradientBins / gradientMax);  // as the count's loop computes it
  return std::clamp(int(std::floor(f)), 0, kGradientBins - 1);
}

std::vector<float> Tf2dHistogram::logImage() const {
  std::vector<float> out(counts.size(), 0.0f);
  uint64_t top = counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
  if (top == 0) return out;
  double norm = 1.0 / std::log1p(double(top));
  for (size_t i = 0; i < counts.size(); ++i) out[i] = float(std::log1p(double(counts[i])) * norm);
  return out;
}

Tf2dHistogram tf2dHistogram(const Volume& v, double gradientMax, const std::atomic<bool>* cancel) {
  Tf2dHistogram h;
  if (v.voxelCount() == 0) return h;
  GradientAt grad(v);
  ValueRange r = storedRange(v);
  h.huLo = std::min(v.toPhysical(r.min), v.toPhysical(r.max));
  h.huHi = std::max(v.toPhysical(r.min), v.toPhysical(r.max));
  if (!(h.huHi > h.huLo)) h.huHi = h.huLo + 1.0;
  h.gradientMax = gradientMax > 0.0 ? gradientMax : percentileGradient(v, grad, cancel);
  if (cancel && *cancel) return {};
  const size_t bins = size_t(Tf2dHistogram::kValueBins) * Tf2dHistogram::kGradientBins;
  std::vector<uint64_t> all(bins, 0);
  std::mutex merge;
  // Each stored value's column, looked up (the division and floor once per value, not voxel).
  std::vector<uint16_t> column(size_t(int(r.max) - int(r.min) + 1));
  for (int sv = r.min; sv <= r.max; ++sv)
    column[size_t(sv - r.min)] = uint16_t(h.columnOf(v.toPhysical(sv)));
  const glm::dvec3 s2 = grad.scale * grad.scale;
  const double rowsPerG = Tf2dHistogram::kGradientBins / h.gradientMax;
  const int nx = v.dims.x, ny = v.dims.y, nz = v.dims.z;
  // One slice per index: each counts into its own table (64 KiB), then adds it once. Rows of
  // the six neighbours by pointer, the faces' neighbours clamped as GradientAt's.
  parallelFor(
      size_t(nz),
      [&](size_t zi) {
        std::vector<uint32_t> local(bins, 0);
        const int z = int(zi);
        for (int y = 0; y < ny; ++y) {
          const int16_t* c = &v.voxels[v.index(0, y, z)];
          const int16_t* ym = &v.voxels[v.index(0, std::max(y - 1, 0), z)];
          const int16_t* yp = &v.voxels[v.index(0, std::min(y + 1, ny - 1), z)];
          const int16_t* zm = &v.voxels[v.index(0, y, std::max(z - 1, 0))];
          const int16_t* zp = &v.voxels[v.index(0, y, std::min(z + 1, nz - 1))];
          for (int x = 0; x < nx; ++x) {
            double gx = c[std::min(x + 1, nx - 1)] - c[std::max(x - 1, 0)];
            double gy = yp[x] - ym[x], gz = zp[x] - zm[x];
            double g = std::sqrt(gx * gx * s2.x + gy * gy * s2.y + gz * gz * s2.z);
            int row = std::min(int(g * rowsPerG), Tf2dHistogram::kGradientBins - 1);
            ++local[size_t(row) * Tf2dHistogram::kValueBins + column[size_t(c[x] - r.min)]];
          }
        }
        std::lock_guard<std::mutex> lock(merge);
        for (size_t k = 0; k < bins; ++k) all[k] += local[k];
      },
      cancel);
  if (cancel && *cancel) return {};
  h.counts = std::move(all);
  h.total = v.voxelCount();
  return h;
}

}  // namespace voxray
