#pragma once
// Min/max of the volume over macro cells, the basis of empty-space skipping. Computed
// once per volume on the host; the device classifies it per transfer function
// (kernels/empty_space/classify.cl) and the raycaster leaps empty cells
// (kernels/empty_space/skip.cl).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace voxray {

struct Volume;

// Cell edge in voxels; kernels/params.cl defines the same CELL.
constexpr int kCellSize = 4;

struct MacroCells {
  glm::ivec3 dims{0};           // cells along x, y, z: ceil(volume dims / kCellSize)
  std::vector<int16_t> minMax;  // per cell, x fastest: min, max (as the kernels' short2)
};

// Cell c covers voxels kCellSize * c - 1 ... kCellSize * (c + 1) along each axis,
// clamped to the volume: every sample whose position falls in the cell reads only
// those voxels, with one to spare. Runs on all hardware threads.
MacroCells computeMacroCells(const Volume& v);

// The rows of cells along z [x, y) whose voxels all lie in slices [FIRST, END) of a volume of
// SLICES slices (out-of-core parts: out_of_core.h); (0, 0) when none does.
glm::ivec2 completeCellRows(int first, int end, int slices);
// Those ROWS' min/max (as MacroCells::minMax, from row ROWS.x) of a volume of DIMS from its
// slices held at SLICES from slice FIRST on; equal to computeMacroCells' rows of the whole.
std::vector<int16_t> computeMacroCellRows(const int16_t* slices, int first, const glm::ivec3& dims,
                                          const glm::ivec2& rows);

}  // namespace voxray
