#pragma once
// Checks a segmentation before anything computes on it or writes it.
#include "voxray/io/segmentation.h"

namespace voxray {

// Throws an input Error naming what is wrong: labels not one per voxel of the grid, a label
// used twice by segments, a segment with label 0.
void checkSegmentation(const Segmentation& s);

// Throws an input Error when the segmentation does not lie on the volume's voxels (other
// dims, spacing, origin or direction), saying both grids.
void checkSameGrid(const Segmentation& s, const Volume& v);

}  // namespace voxray
