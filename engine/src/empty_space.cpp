#include "empty_space.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "cl_context_impl.h"
#include "dvr_occupancy.h"
#include "leap_distances.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/transfer_function.h"
#include "voxray/io/parallel.h"
#include "voxray/io/volume.h"

namespace voxray {

void EmptySpace::upload(ContextImpl& cl, const Volume& v) {
  upload(cl, computeMacroCells(v));
  volume_ = &v;
}

void EmptySpace::upload(ContextImpl& cl, MacroCells cells) {
  range_ = cl::Buffer();  // it may read cells_ in place (below): gone before they are
  cells_ = std::move(cells);
  volume_ = nullptr;
  valueLo_ = INT16_MAX, valueHi_ = INT16_MIN;
  for (size_t c = 0; c + 1 < cells_.minMax.size(); c += 2) {
    valueLo_ = std::min<int>(valueLo_, cells_.minMax[c]);
    valueHi_ = std::max<int>(valueHi_, cells_.minMax[c + 1]);
  }
  shown_.clear();
  size_t n = cells_.minMax.size() / 2;
  clCall([&] {
    // Never written: a CPU device reads the cells where they are (a copy was 4 bytes per 64
    // voxels, 3 % of the volume beside it; issue 38's one host copy).
    const cl_mem_flags where = cl.info.isGpu ? CL_MEM_COPY_HOST_PTR : CL_MEM_USE_HOST_PTR;
    range_ = cl::Buffer(cl.context, CL_MEM_READ_ONLY | where, n * sizeof(cl_short2),
                        cells_.minMax.data());
    occ_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, n);
    // Behind the distances, each cell's adaptive step level (ADAPTIVE dvr frames only).
    leap_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, 2 * n);
    leapBytes_ = 2 * n;
    aheadScratch_ = cl::Buffer();
    scratch_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, n);
    return 0;
  });
  key_.clear();
}

void EmptySpace::replaceRows(ContextImpl& cl, const glm::ivec2& rows, const int16_t* minMax) {
  const size_t row = size_t(cells_.dims.x) * size_t(cells_.dims.y) * 2;
  const size_t at = size_t(rows.x) * row, count = size_t(rows.y - rows.x) * row;
  if (count == 0) return;
  clCall([&] {
    // Blocking, in an in-order queue: mapped once the launches queued before are done with
    // the old rows (a CPU device reads cells_ in place: they change only then).
    void* p = cl.queue.enqueueMapBuffer(range_, CL_TRUE, CL_MAP_WRITE, at * sizeof(int16_t),
                                        count * sizeof(int16_t));
    std::copy_n(minMax, count, cells_.minMax.begin() + ptrdiff_t(at));
    if (p != cells_.minMax.data() + at) std::memcpy(p, minMax, count * sizeof(int16_t));
    cl.queue.enqueueUnmapMemObject(range_, p);
    cl.queue.finish();
    return 0;
  });
  valueLo_ = INT16_MAX, valueHi_ = INT16_MIN;
  for (size_t c = 0; c + 1 < cells_.minMax.size(); c += 2) {
    valueLo_ = std::min<int>(valueLo_, cells_.minMax[c]);
    valueHi_ = std::max<int>(valueHi_, cells_.minMax[c + 1]);
  }
  key_.clear();
}

void EmptySpace::setShownCells(ContextImpl& cl, std::vector<uint8_t> shown) {
  if (shown == shown_) return;
  shown_ = std::move(shown);
  key_.clear();
  if (shown_.empty()) return;
  // classify.cl's dvr test finds no table entry between a min above its max.
  std::vector<int16_t> masked = cells_.minMax;
  for (size_t c = 0; c < shown_.size() && 2 * c + 1 < masked.size(); ++c)
    if (!shown_[c]) masked[2 * c] = INT16_MAX, masked[2 * c + 1] = INT16_MIN;
  clCall([&] {
    shownRange_ = cl::Buffer(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                             masked.size() * sizeof(int16_t), masked.data());
    return 0;
  });
}

void EmptySpace::setOverlayCells(ContextImpl& cl, const std::vector<uint8_t>& cells) {
  if (cells == overlay_) return;
  overlay_ = cells;
  key_.clear();
  if (overlay_.empty()) return;
  clCall([&] {
    overlayBuffer_ = cl::Buffer(cl.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                overlay_.size(), overlay_.data());
    return 0;
  });
}

void EmptySpace::aheadDistances(ContextImpl& cl, const cl_int4& dims) {
  size_t n = cells_.minMax.size() / 2;
  // The distances and, behind them, one region per octant of ray directions; the passes'
  // intermediate regions: two after x, four after y; behind them the iso block bits
  // (isoBlocks). Made on the first iso frame only.
  if (leapBytes_ < 10 * n) {
    leap_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, 10 * n);
    leapBytes_ = 10 * n;
  }
  if (!aheadScratch_()) aheadScratch_ = cl::Buffer(cl.context, CL_MEM_READ_WRITE, 6 * n);
  cl::Kernel pass = cl.kernel("empty_space/classify.cl", "leap_distance_ahead", "");
  const int len[3] = {dims.s[0], dims.s[1], dims.s[2]};
  auto run = [&](const cl::Buffer& in, size_t inAt, const cl::Buffer& out, size_t outAt, int axis,
                 bool positive) {
    size_t lines = n / size_t(len[axis]);  // one work-item per line along axis
    pass.setArg(0, in);
    pass.setArg(1, cl_int(inAt));
    pass.setArg(2, out);
    pass.setArg(3, cl_int(outAt));
    pass.setArg(4, dims);
    pass.setArg(5, cl_int(axis));
    pass.setArg(6, cl_int(axis == 0));
    pass.setArg(7, cl_int(positive ? 1 : -1));
    cl.queue.enqueueNDRangeKernel(pass, cl::NullRange, cl::NDRange((lines + 63) / 64 * 64),
                                  cl::NullRange);
  };
  // Octant o: bit a set where the ray's direction along axis a is > 0 (skip_ahead_lanes.cl).
  for (int sx = 0; sx < 2; ++sx) run(occ_, 0, aheadScratch_, sx * n, 0, sx);
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      run(aheadScratch_, sx * n, aheadScratch_, (2 + sx + 2 * sy) * n, 1, sy);
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz)
        run(aheadScratch_, (2 + sx + 2 * sy) * n, leap_, (1 + sx + 2 * sy + 4 * sz) * n, 2, sz);
}

void EmptySpace::isoBlocks(ContextImpl& cl, const RaycastParams& k) {
  const Volume& v = *volume_;
  const glm::ivec3 n = cells_.dims, d = v.dims;
  const size_t cells = cells_.minMax.size() / 2;
  const float lo = k.values.s[0], hi = k.values.s[1];
  // classify's test and margin (kernels/empty_space/classify.cl), on a block's voxels instead.
  auto meets = [&](float a, float b) { return b + 0.5f >= lo && a - 0.5f <= hi; };
  blocks_.assign(cells, 0);
  parallelFor(size_t(n.z), [&](size_t cz) {
    for (int cy = 0; cy < n.y; ++cy)
      for (int cx = 0; cx < n.x; ++cx) {
        size_t c = (cz * size_t(n.y) + size_t(cy)) * size_t(n.x) + size_t(cx);
        // A block's voxels lie in its cell's min/max: an empty cell's blocks are empty.
        if (!meets(cells_.minMax[2 * c], cells_.minMax[2 * c + 1])) continue;
        uint8_t bits = 0;
        for (int b = 0; b < 8; ++b) {
          // Block (2 cx + bx, ...) holds the samples at p with floor(p / 2) on it (clamped
          // into the grid): trilinear reads voxels 2 bx ... 2 bx + 2 of it, clamped to the
          // volume (nearest: one of them), so their min/max bounds the sample.
          glm::ivec3 b0 = 2 * glm::ivec3(cx, cy, int(cz)) + glm::ivec3(b & 1, (b >> 1) & 1, b >> 2);
          glm::ivec3 a = glm::clamp(2 * b0, glm::ivec3(0), d - 1);
          glm::ivec3 e = glm::clamp(2 * b0 + 2, glm::ivec3(0), d - 1);
          int16_t vmin = INT16_MAX, vmax = INT16_MIN;
          for (int z = a.z; z <= e.z; ++z)
            for (int y = a.y; y <= e.y; ++y)
              for (int x = a.x; x <= e.x; ++x) {
                int16_t s = v.voxels[v.index(x, y, z)];
                vmin = std::min(vmin, s);
                vmax = std::max(vmax, s);
              }
          if (meets(vmin, vmax)) bits |= uint8_t(1u << b);
        }
        blocks_[c] = bits;
      }
  });
  // Blocking: blocks_ is rewritten at the next classification.
  cl.queue.enqueueWriteBuffer(leap_, CL_TRUE, 9 * cells, cells, blocks_.data());
}

void EmptySpace::classify(ContextImpl& cl, const cl::Buffer& params, const cl::Buffer& lutBuffer,
                          const RaycastParams& k, Mode mode, const Lut& lut, bool adaptive,
                          bool packets, bool blockBits) {
  int m = mode == Mode::Iso ? 0 : mode == Mode::Dvr ? 1 : 2;
  // iso depends on the range only (and on what the packets read); dvr on which table
  // entries are not transparent and on where the table sits in stored units.
  std::vector<float> key = {float(m), k.values.s[0], k.values.s[1], float(packets),
                            float(blockBits)};
  if (m == 2) key = {float(m), k.dvr.s[0]};
  std::vector<int> opaque;
  if (m == 1) {
    key = {float(m), k.values.s[2], k.values.s[3]};
    // The levels depend on the colours too, and on the step and the bound.
    if (adaptive) {
      key.insert(key.end(), {k.view.s[2], k.view.s[3], k.dvr.s[3]});
      for (const auto& e : lut.rgba) key.insert(key.end(), {e.r, e.g, e.b, e.a});
    }
    opaque.resize(lut.rgba.size() + 1, 0);
    for (size_t i = 0; i < lut.rgba.size(); ++i) opaque[i + 1] = opaque[i] + (lut.rgba[i].a > 0.0f);
  }
  if (key == key_ && opaque == opaque_) return;
  size_t cells = cells_.minMax.size() / 2;
  clCall([&] {
    cl::CommandQueue& q = cl.queue;
    size_t global = (cells + 63) / 64 * 64;
    if (m == 1) {
      const DvrCellBounds bounds =
          dvrCellBounds(opaque, k.values.s[2], k.values.s[3], valueLo_, valueHi_);
      const cl_int count = cl_int(bounds.from.size());
      // One table, from then to; the asynchronous write reads this copy (the frame waits for
      // its kernel before the next classification).
      boundsUploaded_ = bounds.from;
      boundsUploaded_.insert(boundsUploaded_.end(), bounds.to.begin(), bounds.to.end());
      size_t bytes = std::max<size_t>(boundsUploaded_.size(), 1) * sizeof(cl_int);
      if (bytes > boundsCapacity_) {
        bounds_ = cl::Buffer(cl.context, CL_MEM_READ_ONLY, bytes);
        boundsCapacity_ = bytes;
      }
      if (count > 0)
        q.enqueueWriteBuffer(bounds_, CL_FALSE, 0, boundsUploaded_.size() * sizeof(cl_int),
                             boundsUploaded_.data());
      cl::Kernel kernel = cl.kernel("empty_space/classify.cl", "classify_dvr", "");
      kernel.setArg(0, shown_.empty() ? range_ : shownRange_);
      kernel.setArg(1, bounds_);
      kernel.setArg(2, cl_int(bounds.lo));
      kernel.setArg(3, std::max<cl_int>(count, 1));
      kernel.setArg(4, cl_int(cells));
      kernel.setArg(5, occ_);
      q.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NullRange);
    } else {
      cl::Kernel kernel = cl.kernel("empty_space/classify.cl", "classify", "");
      kernel.setArg(0, range_);
      kernel.setArg(1, params);
      kernel.setArg(2, cl_int(m));
      kernel.setArg(3, cl_int(cells));
      kernel.setArg(4, occ_);
      q.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(global), cl::NullRange);
    }
    if (m == 1 && overlay_.size() == cells) {  // a cell is empty only when both volumes are
      cl::Kernel occupy = cl.kernel("empty_space/classify.cl", "occupy", "");
      occupy.setArg(0, overlayBuffer_);
      occupy.setArg(1, cl_int(cells));
      occupy.setArg(2, occ_);
      q.enqueueNDRangeKernel(occupy, cl::NullRange, cl::NDRange(global), cl::NullRange);
    }
    cl_int4 dims = {{cells_.dims.x, cells_.dims.y, cells_.dims.z, 0}};
    // Only iso packets read the one-sided distances (one ray per work-item leaps by the
    // two-sided ones). First: it may enlarge leap_. Their minimum is then the two-sided
    // distances (the same, at a fraction of the work); otherwise, three passes make them
    // (leap_distances.h).
    const bool oneSided = m == 0 && packets;
    if (oneSided) {
      aheadDistances(cl, dims);
      // Only frames whose packets pass blocks read the bits (ISO_BLOCK_TRIES, 8 lanes): a
      // scan of the occupied cells' voxels on the host, 20-30 ms of CPU per iso change on a
      // 512x512x400 CT, that 16-lane frames do not need.
      if (blockBits) {
        isoBlocks(cl, k);
        ++isoBlockScans_;
      }
      cl::Kernel octants = cl.kernel("empty_space/classify.cl", "leap_distance_from_octants", "");
      octants.setArg(0, leap_);
      octants.setArg(1, cl_int(cells));
      q.enqueueNDRangeKernel(octants, cl::NullRange, cl::NDRange(global), cl::NullRange);
    }
    if (!oneSided) {
      enqueueLeapDistances(cl, occ_, leap_, scratch_, cells_.dims);
    }
    if (adaptive) {
      cl::Kernel level = cl.kernel("empty_space/classify.cl", "adaptive_level", "");
      level.setArg(0, range_);
      level.setArg(1, params);
      level.setArg(2, lutBuffer);
      level.setArg(3, cl_int(cells));
      level.setArg(4, leap_);
      q.enqueueNDRangeKernel(level, cl::NullRange, cl::NDRange(global), cl::NullRange);
    }
    return 0;
  });
  key_ = std::move(key);
  opaque_ = std::move(opaque);
  ++classifications_;
}

}  // namespace voxray
