#pragma once
// The bounding box of a mask and the blocks cut from it: operations run on the part of the
// grid the mask occupies (plus what they can reach) rather than on the whole volume.
#include <algorithm>

#include "segment_itk.h"
#include "voxray/io/segment_mask.h"

namespace voxray {

struct Box {
  glm::ivec3 lo{0}, hi{0};  // [lo, hi)
  bool empty() const { return glm::any(glm::lessThanEqual(hi, lo)); }
  glm::ivec3 dims() const { return hi - lo; }
};

inline Box maskBox(const VoxelGrid& g, const Mask& m) {
  Box b{g.dims, glm::ivec3(0)};
  for (int z = 0; z < g.dims.z; ++z)
    for (int y = 0; y < g.dims.y; ++y) {
      const uint8_t* row = m.data() + g.index(0, y, z);
      const uint8_t* first = std::find(row, row + g.dims.x, uint8_t(1));
      if (first == row + g.dims.x) continue;
      const int x0 = int(first - row);
      int x1 = g.dims.x - 1;
      while (!row[x1]) --x1;
      b.lo = glm::min(b.lo, glm::ivec3(x0, y, z));
      b.hi = glm::max(b.hi, glm::ivec3(x1 + 1, y + 1, z + 1));
    }
  return b;
}

inline Box padded(const Box& b, glm::ivec3 pad, glm::ivec3 dims) {
  return Box{glm::max(b.lo - pad, glm::ivec3(0)), glm::min(b.hi + pad, dims)};
}

inline itk_ops::Block cut(const VoxelGrid& g, const Mask& m, const Box& b) {
  itk_ops::Block out{b.dims(), g.spacingMm, {}};
  out.voxels.resize(size_t(out.dims.x) * size_t(out.dims.y) * size_t(out.dims.z));
  size_t i = 0;
  for (int z = b.lo.z; z < b.hi.z; ++z)
    for (int y = b.lo.y; y < b.hi.y; ++y, i += size_t(out.dims.x))
      std::copy_n(m.data() + g.index(b.lo.x, y, z), out.dims.x, out.voxels.data() + i);
  return out;
}

inline void paste(const itk_ops::Block& block, const Box& b, const VoxelGrid& g, Mask& m) {
  size_t i = 0;
  for (int z = b.lo.z; z < b.hi.z; ++z)
    for (int y = b.lo.y; y < b.hi.y; ++y, i += size_t(block.dims.x))
      std::copy_n(block.voxels.data() + i, block.dims.x, m.data() + g.index(b.lo.x, y, z));
}

}  // namespace voxray
