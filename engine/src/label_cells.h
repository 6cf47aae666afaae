#pragma once
// Which labels each macro cell can show (issue 34): the labels of the voxels in the cell's
// span (kCellSize * c - 1 ... kCellSize * (c + 1) along each axis, as macro_cells.h), which
// holds every voxel nearest to a sample in the cell. With the segment table's factors it
// tells the cells where every sample has opacity 0 (a show mask without the cell's labels,
// a hide mask of all of them), which empty-space skipping may then leap exactly.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/io/segmentation.h"

namespace voxray {

struct LabelCells {
  glm::ivec3 dims{0};                            // as MacroCells::dims
  std::vector<std::array<uint64_t, 4>> present;  // per cell, x fastest: bit l = label l
};

// Runs on all hardware threads.
LabelCells computeLabelCells(const Segmentation& s);
// The cells whose span meets the voxel box LO ... HI (inclusive) again, after an edit there.
void updateLabelCells(LabelCells& cells, const Segmentation& s, glm::ivec3 lo, glm::ivec3 hi);
// Per cell 1 where one of its labels has an opacity factor above 0 in TABLE
// (kernels/segment_table.h), else 0.
std::vector<uint8_t> cellsShown(const LabelCells& cells, const std::vector<glm::vec4>& table);

}  // namespace voxray
