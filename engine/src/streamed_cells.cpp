// streamMacroCells (streamed_cells.h): a source's empty-space cells without holding it.
#include "streamed_cells.h"

#include <algorithm>
#include <cstring>

#include "voxray/io/volume.h"

namespace voxray {

// computeMacroCells of the source's volume without holding it: slices are read GROUP at a
// time, and each cell is made once the slices it covers (4c - 1 to 4c + 4) are in. The
// window of slices starts at a multiple of kCellSize, so computeMacroCells of the window
// spans each of its cells over the same slices as over the whole volume.
MacroCells streamMacroCells(SlabSource& src, int group) {
  const Volume& g = src.geometry();
  MacroCells m;
  m.dims = (g.dims + (kCellSize - 1)) / kCellSize;
  const size_t plane = size_t(m.dims.x) * size_t(m.dims.y);
  m.minMax.resize(plane * size_t(m.dims.z) * 2);
  const size_t slice = size_t(g.dims.x) * size_t(g.dims.y);
  Volume window;
  window.dims = g.dims;
  int first = 0, end = 0, next = 0;  // slices [first, end) in the window; cells from next
  while (next < m.dims.z) {
    const int readEnd = std::min(g.dims.z, end + group);
    window.voxels.resize(size_t(readEnd - first) * slice);
    src.readSlices(end, readEnd, window.voxels.data() + size_t(end - first) * slice);
    end = readEnd;
    int ready = m.dims.z;  // cells whose slices are all read
    if (end < g.dims.z) ready = end >= kCellSize + 1 ? (end - kCellSize - 1) / kCellSize + 1 : 0;
    if (ready <= next) continue;
    window.dims.z = end - first;
    const MacroCells part = computeMacroCells(window);
    const int offset = first / kCellSize;
    std::copy(part.minMax.begin() + ptrdiff_t(size_t(next - offset) * plane * 2),
              part.minMax.begin() + ptrdiff_t(size_t(ready - offset) * plane * 2),
              m.minMax.begin() + ptrdiff_t(size_t(next) * plane * 2));
    next = ready;
    const int keep = std::max(next * kCellSize - kCellSize, 0);
    std::memmove(window.voxels.data(), window.voxels.data() + size_t(keep - first) * slice,
                 size_t(end - keep) * slice * sizeof(int16_t));
    window.voxels.resize(size_t(end - keep) * slice);
    first = keep;
  }
  return m;
}

}  // namespace voxray
