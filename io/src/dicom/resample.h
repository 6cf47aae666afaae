#pragma once
// Resampling of a sheared or unevenly spaced stack onto an orthogonal, uniform grid.
#include <atomic>
#include <cstdint>
#include <vector>

#include "stack_geometry.h"
#include "voxray/io/voxel_memory.h"

namespace voxray::dicom {

struct Resampled {
  VoxelVector voxels;
  size_t padded = 0;  // voxels outside every acquired slice, set to OUTSIDE
};

// SLICES: the stored stack (x fastest, slice by slice) on geometry G.source with slice
// origins ORIGINS. Returns voxels on G.target: trilinear along the normal between the
// two nearest slices, bilinear inside each. Outside the data: OUTSIDE.
Resampled resampleStack(const VoxelVector& slices, const std::vector<glm::dvec3>& origins,
                        const StackGeometry& g, int16_t outside, const std::atomic<bool>* cancel);

}  // namespace voxray::dicom
