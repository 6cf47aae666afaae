// Margins by an exact Euclidean distance transform (Felzenszwalb & Huttenlocher 2012, the
// lower envelope of parabolas, one pass per axis with that axis's spacing). Hand-written:
// ITK's SignedMaurerDistanceMap needs a float image of the whole volume and its dilate/erode
// filters step a voxel kernel, so a 2 mm margin on 0.5 x 0.5 x 3 mm voxels would be a box
// of whole voxels, not 2 mm; this one is exact at every voxel centre, works on the mask's
// box grown by the margin only, and runs its lines on every core.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "mask_box.h"
#include "parallel_rows.h"
#include "voxray/io/error.h"
#include "voxray/io/segment_ops.h"

namespace voxray {
namespace {

constexpr float kFar = std::numeric_limits<float>::max() / 4;

// One line of squared distances f (n values, `stride` apart) becomes min_q (s²(p-q)² + f(q)),
// with z, v, d scratch of n + 1, n, n. Values beyond `limit` become far: the margin only asks
// whether a distance is within it, and a value beyond it stays beyond after any later pass
// (passes only add), so dropping those parabolas keeps the answer exact and the lines short.
void envelope(float* f, int n, size_t stride, double s2, float limit, std::vector<double>& z,
              std::vector<int>& v, std::vector<float>& d) {
  int k = -1;
  for (int q = 0; q < n; ++q) {
    const double fq = f[size_t(q) * stride];
    if (fq >= kFar) continue;
    while (k >= 0) {
      const int p = v[size_t(k)];
      const double fp = f[size_t(p) * stride];
      // Where the parabolas of p and q meet (in index units).
      const double sx = ((fq + s2 * q * q) - (fp + s2 * p * p)) / (2.0 * s2 * (q - p));
      if (sx <= z[size_t(k)]) {
        --k;
        continue;
      }
      z[size_t(k) + 1] = sx;
      break;
    }
    ++k;
    v[size_t(k)] = q;
    if (k == 0) z[0] = -std::numeric_limits<double>::infinity();
    z[size_t(k) + 1] = std::numeric_limits<double>::infinity();
  }
  if (k < 0) return;  // nothing on this line: every value stays far
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[size_t(j) + 1] < q) ++j;
    const int p = v[size_t(j)];
    const float value = float(s2 * double(q - p) * double(q - p) + f[size_t(p) * stride]);
    d[size_t(q)] = value <= limit ? value : kFar;
  }
  for (int q = 0; q < n; ++q) f[size_t(q) * stride] = d[size_t(q)];
}

// A margin reaches only a few voxels along an axis when it is small: then the pass along it is
// the minimum over that window of f + s²k² (k = -reach ... reach), the same exact result as
// the envelope (farther voxels add more than the limit) with contiguous rows, and cheaper up
// to this many voxels in the window.
constexpr int kWindowMax = 9;

// The pass along y by the window, slice by slice in place.
void windowY(std::vector<float>& f, glm::ivec3 d, double s2, int reach, float limit) {
  const size_t nx = size_t(d.x), nxy = nx * size_t(d.y);
  parallelRange(d.z, [&](int z0, int z1) {
    std::vector<float> slice(nxy);
    for (int z = z0; z < z1; ++z) {
      float* out = f.data() + size_t(z) * nxy;
      std::copy_n(out, nxy, slice.data());
      for (int y = 0; y < d.y; ++y) {
        float* row = out + size_t(y) * nx;
        for (int k = -reach; k <= reach; ++k) {
          if (k == 0 || y + k < 0 || y + k >= d.y) continue;
          const float add = float(s2 * k * k);
          const float* src = slice.data() + size_t(y + k) * nx;
          for (size_t x = 0; x < nx; ++x) row[x] = std::min(row[x], src[x] + add);
        }
        for (size_t x = 0; x < nx; ++x)
          if (row[x] > limit) row[x] = kFar;
      }
    }
  });
}

// Squared distance in mm² (up to `limit`, beyond it far) from each voxel of the block to the
// nearest voxel where `source`; with skipZ, along x and y only (the caller windows z).
std::vector<float> squaredDistance(const itk_ops::Block& b, bool source, float limit, bool skipZ) {
  const glm::ivec3 d = b.dims;
  const size_t nx = size_t(d.x), nxy = nx * size_t(d.y);
  std::vector<float> f(b.voxels.size());
  // Along x the input is 0 or far: the distance to the nearest source in the row, by a scan
  // each way (no parabolas needed).
  const double sx2 = b.spacingMm.x * b.spacingMm.x;
  parallelRange(d.z, [&](int z0, int z1) {
    for (size_t row = size_t(z0) * size_t(d.y); row < size_t(z1) * size_t(d.y); ++row) {
      const uint8_t* in = b.voxels.data() + row * nx;
      float* out = f.data() + row * nx;
      int last = -1;
      for (int x = 0; x < d.x; ++x) {
        if ((in[x] != 0) == source) last = x;
        const double dist = last < 0 ? kFar : sx2 * double(x - last) * double(x - last);
        out[x] = dist <= limit ? float(dist) : kFar;
      }
      last = -1;
      for (int x = d.x - 1; x >= 0; --x) {
        if ((in[x] != 0) == source) last = x;
        if (last < 0) continue;
        const double dist = sx2 * double(last - x) * double(last - x);
        if (dist <= limit && float(dist) < out[x]) out[x] = float(dist);
      }
    }
  });
  for (int axis = 1; axis < 3; ++axis) {
    if (axis == 2 && skipZ) break;
    const double s2 = b.spacingMm[axis] * b.spacingMm[axis];
    const int n = d[axis];
    const int reach = int(std::floor(std::sqrt(double(limit) / s2)));
    if (axis == 1 && 2 * reach + 1 <= kWindowMax) {
      windowY(f, d, s2, reach, limit);
      continue;
    }
    const size_t stride = axis == 1 ? nx : nxy;
    // Lines along `axis`, numbered over x and the remaining axis; x innermost, so that
    // neighbouring lines share cache lines.
    const int w = axis == 1 ? 2 : 1;
    const size_t sw = w == 1 ? nx : nxy;
    parallelRange(d[w], [&](int w0, int w1) {
      std::vector<double> z(static_cast<size_t>(n) + 1);
      std::vector<int> v(static_cast<size_t>(n));
      std::vector<float> tmp(static_cast<size_t>(n));
      for (int c = w0; c < w1; ++c)
        for (int a = 0; a < d.x; ++a)
          envelope(f.data() + size_t(c) * sw + size_t(a), n, stride, s2, limit, z, v, tmp);
    });
  }
  return f;
}

}  // namespace

void applyMargin(const VoxelGrid& g, Mask& m, double mm) {
  if (!std::isfinite(mm) || std::abs(mm) > 500.0)
    throw inputError("A margin of " + std::to_string(mm) +
                     " mm: give a distance from -500 to 500 mm (negative shrinks).");
  if (m.size() != g.voxelCount())
    throw Error(Error::Kind::Internal, "applyMargin: the mask does not match the grid");
  if (mm == 0.0) return;
  const Box box = maskBox(g, m);
  if (box.empty()) return;
  const double r = std::abs(mm);
  // A tolerance of 1e-6 mm² keeps a voxel whose centre lies exactly at the margin inside.
  const float r2 = float(r * r + 1e-6);
  glm::ivec3 pad(1);
  if (mm > 0)
    for (int a = 0; a < 3; ++a) pad[a] = int(std::ceil(r / g.spacingMm[a])) + 1;
  const Box b = padded(box, pad, g.dims);
  itk_ops::Block block = cut(g, m, b);
  const bool grow = mm > 0;
  const double sz2 = g.spacingMm.z * g.spacingMm.z;
  const int reachZ = int(std::floor(std::sqrt(double(r2) / sz2)));
  const bool windowZ = 2 * reachZ + 1 <= kWindowMax;
  const auto d2 = squaredDistance(block, grow, r2, windowZ);
  const glm::ivec3 d = block.dims;
  const size_t nxy = size_t(d.x) * size_t(d.y);
  // A voxel is near (within the margin of a voxel of the other kind) when d2 <= r2; with the
  // window along z, when one of the slices within reach says so.
  parallelRange(d.z, [&](int z0, int z1) {
    std::vector<uint8_t> near(nxy);
    for (int z = z0; z < z1; ++z) {
      const size_t at = size_t(z) * nxy;
      if (windowZ) {
        std::fill(near.begin(), near.end(), uint8_t(0));
        for (int k = -reachZ; k <= reachZ; ++k) {
          if (z + k < 0 || z + k >= d.z) continue;
          const float limit = r2 - float(sz2 * k * k);
          const float* src = d2.data() + size_t(z + k) * nxy;
          for (size_t i = 0; i < nxy; ++i) near[i] |= src[i] <= limit;
        }
      } else {
        for (size_t i = 0; i < nxy; ++i) near[i] = d2[at + i] <= r2;
      }
      uint8_t* out = block.voxels.data() + at;
      for (size_t i = 0; i < nxy; ++i) out[i] = grow ? near[i] : uint8_t(out[i] && !near[i]);
    }
  });
  paste(block, b, g, m);
}

}  // namespace voxray
