#include "voxray/engine/coarse_level.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "voxray/io/error.h"
#include "voxray/io/parallel.h"

namespace voxray {

Volume withoutVoxels(const Volume& v) {
  Volume g;
  g.dims = v.dims;
  g.spacingMm = v.spacingMm;
  g.originMm = v.originMm;
  g.direction = v.direction;
  g.slope = v.slope;
  g.intercept = v.intercept;
  g.unit = v.unit;
  g.modality = v.modality;
  g.window = v.window;
  g.suv = v.suv;
  g.timePoint = v.timePoint;
  g.timePoints = v.timePoints;
  g.sourceType = v.sourceType;
  return g;
}

Volume coarseLevel(const Volume& v, int factor) {
  if (factor < 1)
    throw inputError("a coarse level's factor must be 1 or more, not " + std::to_string(factor));
  if (v.voxelCount() == 0 || v.voxels.size() != v.voxelCount())
    throw inputError("the volume is empty or its voxel count does not match its dimensions");
  Volume c = withoutVoxels(v);
  c.study = v.study;
  c.study.sliceSopInstanceUids.clear();  // its slices are not the files'
  const glm::ivec3 n = v.dims;
  c.dims = (n + factor - 1) / factor;
  c.spacingMm = glm::dvec3(n) * v.spacingMm / glm::dvec3(c.dims);
  // The same box: voxel (0,0,0)'s cell corner is origin - direction * spacing / 2 in both.
  c.originMm = v.originMm + v.direction * ((c.spacingMm - v.spacingMm) * 0.5);
  c.voxels.resize(c.voxelCount());
  const size_t rowX = size_t(n.x), slice = size_t(n.x) * size_t(n.y);
  parallelFor(size_t(c.dims.z), [&](size_t cz) {
    // Sums of one coarse slice, then their means: the fine slab is read once, row by row.
    // int32: at most 8^3 values of at most 2^15 each.
    std::vector<int32_t> sum(size_t(c.dims.x) * size_t(c.dims.y), 0);
    const int z0 = int(cz) * factor, z1 = std::min(n.z, z0 + factor);
    const int whole = n.x / factor;  // coarse cells with FACTOR voxels along x
    for (int z = z0; z < z1; ++z)
      for (int y = 0; y < n.y; ++y) {
        const int16_t* row = v.voxels.data() + size_t(z) * slice + size_t(y) * rowX;
        int32_t* out = sum.data() + size_t(y / factor) * size_t(c.dims.x);
        if (factor == 4)  // the usual level: a constant the compiler unrolls and vectorises
          for (int cx = 0; cx < whole; ++cx)
            out[cx] += int32_t(row[4 * cx]) + row[4 * cx + 1] + row[4 * cx + 2] + row[4 * cx + 3];
        else
          for (int cx = 0; cx < whole; ++cx) {
            int32_t t = 0;
            for (int i = 0; i < factor; ++i) t += row[cx * factor + i];
            out[cx] += t;
          }
        for (int x = whole * factor; x < n.x; ++x) out[whole] += row[x];
      }
    int16_t* dst = c.voxels.data() + cz * size_t(c.dims.x) * size_t(c.dims.y);
    const int zn = z1 - z0;
    for (int cy = 0; cy < c.dims.y; ++cy) {
      const int yn = std::min(n.y, (cy + 1) * factor) - cy * factor;
      for (int cx = 0; cx < c.dims.x; ++cx) {
        const int xn = std::min(n.x, (cx + 1) * factor) - cx * factor;
        const size_t i = size_t(cy) * size_t(c.dims.x) + size_t(cx);
        // Round half away from zero: the nearest stored value to the exact mean.
        dst[i] = int16_t(std::lround(double(sum[i]) / double(xn * yn * zn)));
      }
    }
  });
  return c;
}

int coarseFactorFor(const Volume& v, size_t maxVoxels) {
  for (int f : {1, 2, 4}) {
    const glm::ivec3 c = (v.dims + f - 1) / f;
    if (size_t(c.x) * size_t(c.y) * size_t(c.z) <= maxVoxels) return f;
  }
  return 8;
}

}  // namespace voxray
