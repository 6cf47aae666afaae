#pragma once
// The path tracer's majorant grid: the largest extinction (per mm) any sample inside each
// cell of kPathCell^3 voxels can have under the frame's table, so that tracking leaps
// empty cells and takes short steps only where the volume is dense
// (kernels/lighting/path_trace.cl). A trilinear (or nearest) sample in a cell reads voxels from one
// before the cell to one after it, and the table interpolates between entries, so the bound is the
// largest opacity of the entries spanning those voxels' value range.
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/transfer_function.h"

namespace voxray {

struct Volume;

constexpr int kPathCell = 8;  // voxels per cell edge (path_trace.cl: PT_CELL)

class PathMajorants {
 public:
  // The cells' value ranges: once per volume (one pass over the voxels).
  void setVolume(const Volume& v);
  // The grid for a table: sigma = -ln(1 - min(a, cap)) / referenceStepMm per cell.
  const std::vector<float>& update(const Lut& lut, double referenceStepMm, double cap);
  glm::ivec3 dims() const { return dims_; }

 private:
  glm::ivec3 dims_{0};
  std::vector<glm::i16vec2> range_;  // min, max stored value per cell
  std::vector<float> sigma_;
};

}  // namespace voxray
