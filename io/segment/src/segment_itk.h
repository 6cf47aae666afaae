#pragma once
// The operations done with ITK (segment_itk.cpp), or the stubs that say they are not in this
// build (segment_itk_unavailable.cpp: ITK 5.2's headers build with GCC only). Each works on a
// block of the mask (x fastest) with the grid's spacing.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace voxray::itk_ops {

struct Block {
  glm::ivec3 dims{0};
  glm::dvec3 spacingMm{1.0};
  std::vector<uint8_t> voxels;  // 0/1
};

// Island sizes largest first; labels[i] is the island number of voxel i (0 = background,
// 1 = the largest, ...).
struct Islands {
  std::vector<uint32_t> labels;
  std::vector<uint64_t> sizes;  // sizes[n - 1]: voxels of island n
};
Islands islands(const Block& b, bool fullyConnected);

// radius in voxels per axis (a ball in mm becomes an ellipsoid of voxels).
void median(Block& b, glm::ivec3 radius);
void closing(Block& b, glm::ivec3 radius);
void opening(Block& b, glm::ivec3 radius);
// ITK's BinaryFillholeImageFilter: kept to compare with fillHoles (segment_ops.cpp) in the
// tests and the bench.
void fillHoles(Block& b);

}  // namespace voxray::itk_ops
