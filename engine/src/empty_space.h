#pragma once
// The device side of empty-space skipping: each macro cell's min/max (uploaded once per
// volume) and its occupancy for the current frame, reclassified on the device only when
// the iso range or the transfer function's opacity changes.
#include <cstdint>
#include <vector>

#include <CL/opencl.hpp>

#include "kernel_params.h"
#include "macro_cells.h"

namespace voxray {

struct ContextImpl;
struct Lut;
enum class Mode;

class EmptySpace {
 public:
  // Computes the macro cells of v on the host and uploads them.
  void upload(ContextImpl& cl, const Volume& v);
  // The same from cells computed elsewhere (an out-of-core volume's, streamed: out_of_core.h).
  // Without the volume, iso packets' block bits cannot be made: their frames must not ask.
  void upload(ContextImpl& cl, MacroCells cells);
  // Replaces the cell rows along z from ROWS.x to ROWS.y with MINMAX (as MacroCells::minMax)
  // on the host and the device, once the queue is done with them; the next classification
  // follows (an out-of-core volume's rows, found as its parts are first read).
  void replaceRows(ContextImpl& cl, const glm::ivec2& rows, const int16_t* minMax);
  // Brings the occupancy up to date for a frame whose parameters k are already enqueued
  // in params and lutBuffer (the queue is in order). mip needs none: it reads the min/max
  // directly. adaptive (dvr): also each cell's step level (kernels/empty_space/classify.cl,
  // adaptive_level) behind the distances in leap(). iso: packets also read the one-sided
  // distances, and with blockBits (ISO_BLOCK_TRIES > 0) the iso block bits.
  void classify(ContextImpl& cl, const cl::Buffer& params, const cl::Buffer& lutBuffer,
                const RaycastParams& k, Mode mode, const Lut& lut, bool adaptive, bool packets,
                bool blockBits);
  // Label-aware dvr (issue 34): per cell 0 where no sample can show (LabelCells,
  // cellsShown), which dvr then classifies empty whatever its values; empty: no such cells.
  // The next dvr classification follows a change.
  void setShownCells(ContextImpl& cl, std::vector<uint8_t> shown);
  // Fused dvr (issue 36): per cell 1 where the overlay may show (overlay_cells.h), which dvr
  // then classifies occupied whatever the volume's values; empty: none. The next dvr
  // classification follows a change. (The raycaster also marks here the cells where a
  // segment's own transfer function may show: segment_tf.h, segmentTfCells.)
  void setOverlayCells(ContextImpl& cl, const std::vector<uint8_t>& cells);
  const glm::ivec3& dims() const { return cells_.dims; }
  const MacroCells& cells() const { return cells_; }
  // The smallest and largest stored value of the volume (every voxel lies in a cell): what
  // storedRange(volume) gives, without another pass over it.
  int valueLo() const { return valueLo_; }
  int valueHi() const { return valueHi_; }
  const cl::Buffer& range() const { return range_; }
  // Per cell, the chessboard distance in cells to the nearest occupied one (0: occupied),
  // capped at MAX_LEAP (kernels/empty_space/classify.cl); then, after every cell's, each cell's
  // adaptive step level (valid after an adaptive dvr classification), or after an iso
  // classification for packets the eight one-sided distances
  // (kernels/empty_space/skip_ahead_lanes.cl) and, where ISO_BLOCK_TRIES > 0 (8-lane packets), each
  // cell's eight iso block bits (isoBlocks).
  const cl::Buffer& leap() const { return leap_; }
  int classifications() const { return classifications_; }
  int isoBlockScans() const { return isoBlockScans_; }

 private:
  // The one-sided distances of iso packets, one region per octant behind the distances.
  void aheadDistances(ContextImpl& cl, const cl_int4& dims);
  // For iso packets, per macro cell one bit per 2^3 voxel block: whether a sample in the
  // block can hit the iso range (kernels/empty_space/skip_ahead_lanes.cl, iso_block_emptyN). Made
  // on the host from the volume, for occupied cells only (about 4 % of a CT's at bone).
  void isoBlocks(ContextImpl& cl, const RaycastParams& k);

  MacroCells cells_;
  const Volume* volume_ = nullptr;  // the raycaster's, which outlives this
  std::vector<uint8_t> blocks_;     // isoBlocks' bits, for the upload
  cl::Buffer range_, occ_, leap_, scratch_;
  size_t leapBytes_ = 0;
  int valueLo_ = 0, valueHi_ = -1;  // the cells' values, the dvr bounds' extent
  cl::Buffer bounds_;               // DvrCellBounds, from then to
  std::vector<int32_t> boundsUploaded_;
  size_t boundsCapacity_ = 0;
  cl::Buffer aheadScratch_;
  std::vector<uint8_t> shown_;    // setShownCells
  cl::Buffer shownRange_;         // range_ with the cells not shown empty (min above max)
  std::vector<uint8_t> overlay_;  // setOverlayCells
  cl::Buffer overlayBuffer_;
  // What the occupancy was classified for; equal keys skip the work.
  std::vector<float> key_;
  std::vector<int> opaque_;
  int classifications_ = 0, isoBlockScans_ = 0;
};

}  // namespace voxray
