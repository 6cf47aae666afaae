#include <algorithm>
#include <cstring>

#include "streamed_cells.h"
#include "voxray/io/error.h"
#include "voxray/io/volume.h"

namespace voxray {

namespace {

// Slices [w0, w1) of the filled volume: the slab's where it has them, else FILL. Streamed a
// group at a time (streamMacroCells), so that no copy of the slab is made: a rank's peak
// memory is its slab (tests/mpi/rank_memory.py).
class FilledWindow : public SlabSource {
 public:
  FilledWindow(const Volume& slab, int first, int w0, int w1, int16_t fill)
      : slab_(slab), first_(first), w0_(w0), fill_(fill) {
    geometry_.dims = {slab.dims.x, slab.dims.y, w1 - w0};
  }
  const Volume& geometry() const override { return geometry_; }
  void readSlices(int first, int end, int16_t* dest) override {
    const size_t slice = size_t(geometry_.dims.x) * size_t(geometry_.dims.y);
    for (int z = first; z < end; ++z, dest += slice) {
      const int k = w0_ + z - first_;  // the slab's slice
      if (k >= 0 && k < slab_.dims.z)
        std::memcpy(dest, slab_.voxels.data() + size_t(k) * slice, slice * sizeof(int16_t));
      else
        std::fill(dest, dest + slice, fill_);
    }
  }
  const Volume& coarse() override { throw inputError("a filled window has no coarse level"); }
  std::string describe() const override { return "a slab's window"; }

 private:
  const Volume& slab_;
  int first_, w0_;
  int16_t fill_;
  Volume geometry_;
};

}  // namespace

// The cells are computeMacroCells' of a window: the slab and at least 5 filler slices on either
// side (where the volume has them), starting at a multiple of kCellSize so that its cells are
// the volume's. A cell of the volume spans slices 4c - 1 ... 4c + 4: one cut by the window's
// edge keeps a filler slice inside it, and the fill is at most every value, so its min (the
// fill) and max are those of the whole span. Cells beyond the window span filler alone.
MacroCells slabMacroCells(const Volume& slab, int first, int totalSlices, int16_t fill) {
  const int end = first + slab.dims.z;
  const int w0 = std::max(first - (kCellSize + 1), 0) / kCellSize * kCellSize;
  const int w1 = std::min(end + kCellSize + 1, totalSlices);
  FilledWindow window(slab, first, w0, w1, fill);
  const MacroCells part = streamMacroCells(window, 16 * kCellSize);
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
