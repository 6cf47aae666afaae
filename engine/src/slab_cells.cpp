#include <algorithm>

#include "streamed_cells.h"
#include "voxray/io/volume.h"

namespace voxray {

// The cells are computeMacroCells' of a window: the slab and at least 5 filler slices on either
// side (where the volume has them), starting at a multiple of kCellSize so that its cells are
// the volume's. A cell of the volume spans slices 4c - 1 ... 4c + 4: one cut by the window's
// edge keeps a filler slice inside it, and the fill is at most every value, so its min (the
// fill) and max are those of the whole span. Cells beyond the window span filler alone.
MacroCells slabMacroCells(const Volume& slab, int first, int totalSlices, int16_t fill) {
  const int end = first + slab.dims.z;
  const int w0 = std::max(first - (kCellSize + 1), 0) / kCellSize * kCellSize;
  const int w1 = std::min(end + kCellSize + 1, totalSlices);
  const size_t slice = size_t(slab.dims.x) * size_t(slab.dims.y);
  Volume window;
  window.dims = {slab.dims.x, slab.dims.y, w1 - w0};
  window.voxels.assign(size_t(w1 - w0) * slice, fill);
  std::copy(slab.voxels.begin(), slab.voxels.end(),
            window.voxels.begin() + std::ptrdiff_t(size_t(first - w0) * slice));
  const MacroCells part = computeMacroCells(window);
  MacroCells m;
  m.dims = glm::ivec3(slab.dims.x, slab.dims.y, totalSlices);
  m.dims = (m.dims + (kCellSize - 1)) / kCellSize;
  const size_t plane = size_t(m.dims.x) * size_t(m.dims.y);
  m.minMax.assign(plane * size_t(m.dims.z) * 2, fill);
  std::copy(part.minMax.begin(), part.minMax.end(),
            m.minMax.begin() + std::ptrdiff_t(size_t(w0 / kCellSize) * plane * 2));
  return m;
}

}  // namespace voxray
