#pragma once
// Empty-space skipping stays exact with an overlay (issue 36): a base macro cell (macro_cells.h)
// may be leapt only where the overlay shows nothing either. Per base cell, the overlay voxels
// any sample in the cell can read (the cell's span mapped into the overlay's grid, its
// bounding box and one voxel more for trilinear), their min/max, and whether the overlay's
// table has an entry with opacity > 0 that values in that range can interpolate from (one
// entry of margin, as kernels/empty_space/classify.cl).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "voxray/engine/transfer_function.h"

namespace voxray {

struct Volume;

// Per base cell (x fastest, MacroCells::dims of BASE) 1 where the overlay may show.
std::vector<uint8_t> overlayCells(const Volume& base, const Volume& overlay, const Lut& lut,
                                  const glm::dmat4& map);

}  // namespace voxray
