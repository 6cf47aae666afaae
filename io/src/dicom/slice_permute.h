#pragma once
// The reorder of slices decoded in the order their files arrived (a PACS retrieval) into
// the stack's order, in place.
#include <cstddef>
#include <vector>

#include "voxray/io/voxel_memory.h"

namespace voxray::dicom {

// Moves slice SOURCE[k] of VOXELS to slice k, for every k (SOURCE is a permutation of
// 0..SOURCE.size()-1; slice k is at k * SLICE_SIZE). Where slices are whole pages of a block
// of their own (voxel_memory.h: 2 MiB or more), their pages are moved (mremap) instead of
// their bytes: a 400-slice CT that arrived out of order was ~18 ms of copies at the end of
// `pacs get` (issue 39 item 8). Elsewhere, or where the kernel refuses, the bytes are copied.
void permuteSlices(VoxelVector& voxels, size_t sliceSize, const std::vector<size_t>& source);

// Whether permuteSlices moves pages for slices of SLICE_SIZE in VOXELS (tests).
bool slicesMoveAsPages(const VoxelVector& voxels, size_t sliceSize);

}  // namespace voxray::dicom
