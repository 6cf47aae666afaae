// Margins by an exact Euclidean distance transform (Felzenszwalb & Huttenlocher 2012, the
// lower envelope of parabolas, one pass per axis with that axis's spacing). Hand-written:
// ITK's SignedMaurerDistanceMap needs a float image of the whole volume and its dilate/erode
// filters step a voxel kernel, so a 2 mm margin on 0.5 x 0.5 x 3 mm voxels would be a box
// of whole voxels, not 2 mm; this one is exact at every voxel centre, works on the mask's
// box grown by the margin only, and runs its lines on every core.
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
// with z, v, d scratch of n + 1, n, n.
void envelope(float* f, int n, size_t stride, double s2, std::vector<double>& z,
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
    d[size_t(q)] = float(s2 * double(q - p) * double(q - p) + f[size_t(p) * stride]);
  }
  for (int q = 0; q < n; ++q) f[size_t(q) * stride] = d[size_t(q)];
}

// Squared distance in mm² from each voxel of the block to the nearest voxel where `source`.
std::vector<float> squaredDistance(const itk_ops::Block& b, bool source) {
  const glm::ivec3 d = b.dims;
  std::vector<float> f(b.voxels.size());
  for (size_t i = 0; i < f.size(); ++i) f[i] = (b.voxels[i] != 0) == source ? 0.0f : kFar;
  const size_t nx = size_t(d.x), nxy = nx * size_t(d.y);
  for (int axis = 0; axis < 3; ++axis) {
    const double s2 = b.spacingMm[axis] * b.spacingMm[axis];
    const int n = d[axis];
    const size_t stride = axis == 0 ? 1 : axis == 1 ? nx : nxy;
    // Lines along `axis`, numbered over the other two axes.
    const int u = axis == 0 ? 1 : 0, w = axis == 2 ? 1 : 2;
    const size_t su = u == 0 ? 1 : nx, sw = w == 1 ? nx : nxy;
    parallelRange(d[w], [&](int w0, int w1) {
      std::vector<double> z(size_t(n) + 1);
      std::vector<int> v(static_cast<size_t>(n));
      std::vector<float> tmp(static_cast<size_t>(n));
      for (int c = w0; c < w1; ++c)
        for (int a = 0; a < d[u]; ++a)
          envelope(f.data() + size_t(c) * sw + size_t(a) * su, n, stride, s2, z, v, tmp);
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
  if (mm > 0) {
    const auto d2 = squaredDistance(block, true);
    for (size_t i = 0; i < d2.size(); ++i) block.voxels[i] = d2[i] <= r2;
  } else {
    // Background outside the block but inside the grid lies beyond the padding voxel, which
    // is background itself and nearer, so the block alone gives the right distances.
    const auto d2 = squaredDistance(block, false);
    for (size_t i = 0; i < d2.size(); ++i) block.voxels[i] = block.voxels[i] && d2[i] > r2;
  }
  paste(block, b, g, m);
}

}  // namespace voxray
