#include "surface_field.h"

#include <algorithm>
#include <cmath>

#include "surface_layer.h"  // kernels/: the block edge
#include "voxray/io/parallel.h"

namespace voxray {

namespace {

// Taps of a normalised Gaussian of SIGMA voxels out to 3 sigma (one tap at sigma 0).
std::vector<float> gaussianTaps(float sigma) {
  if (sigma <= 0.0f) return {1.0f};
  const int radius = int(std::ceil(3.0f * sigma));
  std::vector<float> w(size_t(2 * radius + 1));
  float sum = 0.0f;
  for (int i = -radius; i <= radius; ++i)
    sum += w[size_t(i + radius)] = std::exp(-0.5f * float(i * i) / (sigma * sigma));
  for (float& x : w) x /= sum;
  return w;
}

// One separable pass along AXIS over a float grid of DIMS (clamped at the edges, where the
// padding holds zeros). Along y and z whole x rows are combined (contiguous, vectorised) rather
// than one strided line at a time.
void blurAxis(std::vector<float>& g, glm::ivec3 dims, int axis, const std::vector<float>& taps) {
  const int radius = int(taps.size() / 2);
  const int n = dims[axis];
  const size_t nx = size_t(dims.x);
  if (axis == 0) {
    parallelFor(size_t(dims.y) * size_t(dims.z), [&](size_t line) {
      float* row = g.data() + line * nx;
      std::vector<float> src(row, row + nx);
      for (int i = 0; i < n; ++i) {
        float s = 0.0f;
        for (int k = -radius; k <= radius; ++k)
          s += taps[size_t(k + radius)] * src[size_t(std::clamp(i + k, 0, n - 1))];
        row[i] = s;
      }
    });
    return;
  }
  // The rows of one y (axis z) or one z (axis y), n of them `stride` floats apart.
  const size_t stride = axis == 1 ? nx : nx * size_t(dims.y);
  const int other = axis == 1 ? dims.z : dims.y;
  const size_t otherStep = axis == 1 ? nx * size_t(dims.y) : nx;
  parallelFor(size_t(other), [&](size_t o) {
    float* base = g.data() + o * otherStep;
    std::vector<float> src(size_t(n) * nx);
    for (int i = 0; i < n; ++i)
      std::copy(base + size_t(i) * stride, base + size_t(i) * stride + nx,
                src.begin() + std::ptrdiff_t(size_t(i) * nx));
    for (int i = 0; i < n; ++i) {
      float* out = base + size_t(i) * stride;
      std::fill(out, out + nx, 0.0f);
      for (int k = -radius; k <= radius; ++k) {
        const float w = taps[size_t(k + radius)];
        const float* in = src.data() + size_t(std::clamp(i + k, 0, n - 1)) * nx;
        for (size_t x = 0; x < nx; ++x) out[x] += w * in[x];
      }
    }
  });
}

// The block flags of FIELD for blocks BLO ... BHI (inclusive): a block may hold the level where
// one of its voxels, or of the next voxel along each axis (trilinear reads reach them), is at
// least 128 (0.5 rounds to it).
void flagBlocks(SurfaceField& f, glm::ivec3 blo, glm::ivec3 bhi) {
  constexpr int kBlock = SURFACE_BLOCK;
  parallelFor(size_t(bhi.z - blo.z + 1), [&](size_t k) {
    const int bz = blo.z + int(k);
    for (int by = blo.y; by <= bhi.y; ++by)
      for (int bx = blo.x; bx <= bhi.x; ++bx) {
        const glm::ivec3 b(bx, by, bz);
        const glm::ivec3 a = b * kBlock, e = glm::min(a + kBlock, f.dims - 1);
        bool any = false;
        for (int z = a.z; z <= e.z && !any; ++z)
          for (int y = a.y; y <= e.y && !any; ++y)
            for (int x = a.x; x <= e.x && !any; ++x)
              any = f.values[(size_t(z) * f.dims.y + y) * f.dims.x + x] >= 128;
        f.blocks[(size_t(b.z) * f.blockDims.y + b.y) * f.blockDims.x + b.x] = any ? 1 : 0;
      }
  });
}

// The field's values over its voxels RLO ... RHI (field coordinates, inclusive) from SEG's mask:
// the mask over that box and the filter's reach (clamped to the field's box, as a whole build
// clamps), filtered, and the box's part written back. Each separable pass reads along its own
// axis only, so the box's values are a whole build's.
void filterRegion(SurfaceField& f, const Segmentation& seg, const std::vector<float>& taps,
                  glm::ivec3 rlo, glm::ivec3 rhi) {
  const int radius = int(taps.size() / 2);
  const glm::ivec3 slo = glm::max(rlo - radius, glm::ivec3(0));
  const glm::ivec3 shi = glm::min(rhi + radius, f.dims - 1);
  const glm::ivec3 sd = shi - slo + 1;
  std::vector<float> g(size_t(sd.x) * sd.y * sd.z, 0.0f);
  const glm::ivec3 vd = seg.grid.dims;
  parallelFor(size_t(sd.z), [&](size_t k) {
    for (int y = 0; y < sd.y; ++y)
      for (int x = 0; x < sd.x; ++x) {
        const glm::ivec3 p = glm::ivec3(x, y, int(k)) + slo + f.lo;  // in the label map
        if (glm::any(glm::lessThan(p, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(p, vd)))
          continue;
        if (seg.labels[seg.grid.index(p.x, p.y, p.z)] == f.label)
          g[(k * sd.y + size_t(y)) * sd.x + size_t(x)] = 1.0f;
      }
  });
  // A separable Gaussian by hand: the engine links no ITK, and three passes of a few taps over
  // the segment's box are a few lines.
  if (taps.size() > 1)
    for (int axis = 0; axis < 3; ++axis) blurAxis(g, sd, axis, taps);
  parallelFor(size_t(rhi.z - rlo.z + 1), [&](size_t k) {
    const int z = rlo.z + int(k);
    for (int y = rlo.y; y <= rhi.y; ++y)
      for (int x = rlo.x; x <= rhi.x; ++x) {
        const glm::ivec3 q = glm::ivec3(x, y, z) - slo;
        const float v = g[(size_t(q.z) * sd.y + q.y) * sd.x + q.x];
        f.values[(size_t(z) * f.dims.y + y) * f.dims.x + x] =
            uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
      }
  });
}

}  // namespace

SurfaceField buildSurfaceField(const Segmentation& seg, uint8_t label, float sigmaVoxels) {
  SurfaceField f;
  f.label = label;
  const glm::ivec3 d = seg.grid.dims;
  // The segment's voxel box, a z plane per task.
  std::vector<glm::ivec3> plo(size_t(d.z), glm::ivec3(INT32_MAX)), phi(size_t(d.z), glm::ivec3(-1));
  parallelFor(size_t(d.z), [&](size_t z) {
    const uint8_t* plane = seg.labels.data() + z * size_t(d.x) * size_t(d.y);
    for (int y = 0; y < d.y; ++y)
      for (int x = 0; x < d.x; ++x)
        if (plane[size_t(y) * d.x + x] == label) {
          plo[z] = glm::min(plo[z], glm::ivec3(x, y, int(z)));
          phi[z] = glm::max(phi[z], glm::ivec3(x, y, int(z)));
        }
  });
  glm::ivec3 lo(INT32_MAX), hi(-1);
  for (int z = 0; z < d.z; ++z)
    if (phi[size_t(z)].x >= 0) lo = glm::min(lo, plo[size_t(z)]), hi = glm::max(hi, phi[size_t(z)]);
  if (hi.x < 0) return f;  // no voxel: no surface
  const std::vector<float> taps = gaussianTaps(sigmaVoxels);
  // Padded by the filter's reach plus one voxel of zeros, so that the field falls below 0.5
  // inside its box and a ray never meets a surface at the box's faces. (Beyond the label
  // map the field may reach outside it: the rays' clip box cuts it there.)
  const int pad = int(taps.size() / 2) + 1;
  f.lo = lo - pad;
  f.dims = hi - lo + 1 + 2 * pad;
  f.coreLo = lo;
  f.coreHi = hi;
  f.sigma = sigmaVoxels;
  f.values.assign(size_t(f.dims.x) * f.dims.y * f.dims.z, 0);
  filterRegion(f, seg, taps, glm::ivec3(0), f.dims - 1);
  f.blockDims = (f.dims + SURFACE_BLOCK - 1) / SURFACE_BLOCK;
  f.blocks.assign(size_t(f.blockDims.x) * f.blockDims.y * f.blockDims.z, 0);
  flagBlocks(f, glm::ivec3(0), f.blockDims - 1);
  return f;
}

bool updateSurfaceField(SurfaceField& f, const Segmentation& seg, glm::ivec3 lo, glm::ivec3 hi) {
  if (f.empty()) return false;
  lo = glm::max(lo, glm::ivec3(0));
  hi = glm::min(hi, seg.grid.dims - 1);
  if (glm::any(glm::greaterThan(lo, hi))) return true;  // nothing edited
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x)
        if (seg.labels[seg.grid.index(x, y, z)] == f.label &&
            (glm::any(glm::lessThan(glm::ivec3(x, y, z), f.coreLo)) ||
             glm::any(glm::greaterThan(glm::ivec3(x, y, z), f.coreHi))))
          return false;  // grown out of its box
  const std::vector<float> taps = gaussianTaps(f.sigma);
  const int radius = int(taps.size() / 2);
  const glm::ivec3 rlo = glm::max(lo - radius - f.lo, glm::ivec3(0));
  const glm::ivec3 rhi = glm::min(hi + radius - f.lo, f.dims - 1);
  if (glm::any(glm::greaterThan(rlo, rhi))) return true;  // beyond its reach
  filterRegion(f, seg, taps, rlo, rhi);
  // Blocks whose voxels (and next ones) meet the region.
  const glm::ivec3 blo = glm::max(rlo - 1, glm::ivec3(0)) / SURFACE_BLOCK;
  const glm::ivec3 bhi = rhi / SURFACE_BLOCK;
  flagBlocks(f, blo, glm::min(bhi, f.blockDims - 1));
  return true;
}

bool surfaceFieldTouched(const SurfaceField& field, const Segmentation& seg, glm::ivec3 lo,
                         glm::ivec3 hi) {
  if (!field.empty()) {
    const glm::ivec3 flo = field.lo, fhi = field.lo + field.dims - 1;
    if (glm::all(glm::lessThanEqual(lo, fhi)) && glm::all(glm::lessThanEqual(flo, hi))) return true;
  }
  lo = glm::max(lo, glm::ivec3(0));
  hi = glm::min(hi, seg.grid.dims - 1);
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x)
        if (seg.labels[seg.grid.index(x, y, z)] == field.label) return true;
  return false;
}

}  // namespace voxray
