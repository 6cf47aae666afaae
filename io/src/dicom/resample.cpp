#include "resample.h"

#include <algorithm>
#include <cmath>

#include "voxray/io/parallel.h"

namespace voxray::dicom {

Resampled resampleStack(const VoxelVector& slices, const std::vector<glm::dvec3>& origins,
                        const StackGeometry& g, int16_t outside, const std::atomic<bool>* cancel) {
  const Grid& s = g.source;
  const Grid& t = g.target;
  const glm::dvec3 row = s.axes[0], col = s.axes[1], n = s.axes[2];
  const int nx = s.dims.x, ny = s.dims.y, nz = s.dims.z;
  const size_t sliceSize = size_t(nx) * size_t(ny);
  const std::vector<double>& d = g.offsets;  // ascending along n
  VoxelVector out(size_t(t.dims.x) * t.dims.y * t.dims.z, outside);
  std::vector<size_t> filled(size_t(t.dims.z), 0);  // per target slice: no shared counter

  // Bilinear sample of slice K at voxel coordinates (u, v); NaN outside.
  auto sample = [&](int k, double u, double v) -> double {
    if (u < -0.5 || v < -0.5 || u > nx - 0.5 || v > ny - 0.5) return NAN;
    u = std::clamp(u, 0.0, double(nx - 1));
    v = std::clamp(v, 0.0, double(ny - 1));
    int x0 = std::min(int(u), nx - 2 < 0 ? 0 : nx - 2),
        y0 = std::min(int(v), ny - 2 < 0 ? 0 : ny - 2);
    int x1 = std::min(x0 + 1, nx - 1), y1 = std::min(y0 + 1, ny - 1);
    double fx = u - x0, fy = v - y0;
    const int16_t* p = slices.data() + size_t(k) * sliceSize;
    double a = p[size_t(y0) * nx + x0] * (1 - fx) + p[size_t(y0) * nx + x1] * fx;
    double b = p[size_t(y1) * nx + x0] * (1 - fx) + p[size_t(y1) * nx + x1] * fx;
    return a * (1 - fy) + b * fy;
  };

  parallelFor(
      size_t(t.dims.z),
      [&](size_t kz) {
        // An end slice stands for the slab half a gap beyond its plane, as a pixel stands
        // for half a pixel beyond its centre: points there take the end slice's values
        // instead of padding, so the grid's cells around that slice's pixels hold its data.
        const double before = 0.5 * (d[1] - d[0]), after = 0.5 * (d[nz - 1] - d[nz - 2]);
        for (int j = 0; j < t.dims.y; ++j) {
          int16_t* dst = out.data() + (kz * t.dims.y + size_t(j)) * t.dims.x;
          for (int i = 0; i < t.dims.x; ++i) {
            glm::dvec3 x = t.origin + double(i) * t.spacing.x * t.axes[0] +
                           double(j) * t.spacing.y * t.axes[1] +
                           double(kz) * t.spacing.z * t.axes[2];
            double along = glm::dot(x - origins[0], n);
            if (along < d.front() - before || along > d.back() + after) continue;
            int b = int(std::upper_bound(d.begin(), d.end(), along) - d.begin());
            b = std::clamp(b, 1, nz - 1);
            int a = b - 1;
            double w = std::clamp((along - d[a]) / (d[b] - d[a]), 0.0, 1.0);
            glm::dvec3 ra = x - origins[a], rb = x - origins[b];
            // A slice of no weight gives no value (beyond an end slice, only that slice).
            double va =
                w < 1 ? sample(a, glm::dot(ra, row) / s.spacing.x, glm::dot(ra, col) / s.spacing.y)
                      : NAN;
            double vb =
                w > 0 ? sample(b, glm::dot(rb, row) / s.spacing.x, glm::dot(rb, col) / s.spacing.y)
                      : NAN;
            if (std::isnan(va) && std::isnan(vb)) continue;
            if (std::isnan(va)) va = vb;  // the edge of a sheared slice: nearest data
            if (std::isnan(vb)) vb = va;
            dst[i] = int16_t(std::lround(va * (1 - w) + vb * w));
            ++filled[kz];
          }
        }
      },
      cancel);
  size_t inside = 0;
  for (size_t count : filled) inside += count;
  const size_t total = out.size();
  return {std::move(out), total - inside};
}

}  // namespace voxray::dicom
