#pragma once
// The segmentation operations on binary masks (segment_mask.h) of a voxel grid: the seeded
// region, islands, holes, margins and smoothing in millimetres, and the logical operations
// between segments. All Qt-free, shared by the workstation's editor and voxray-cli segment
// through segment_recipe.h. Every function throws voxray::Error (Input) for bad arguments.
#include <cstdint>

#include <glm/glm.hpp>

#include "voxray/io/segment_mask.h"
#include "voxray/io/segmentation.h"

namespace voxray {

// Which neighbours touch: faces only (6) or faces, edges and corners (26).
enum class Connectivity { Faces6 = 6, Full26 = 26 };

// The connected region of voxels within the range that contains the seed (voxel indices).
// Throws when the seed lies outside the volume or its own value is outside the range.
Mask seededRegion(const Volume& v, HuRange range, glm::ivec3 seed,
                  Connectivity c = Connectivity::Faces6);

// Islands: the connected parts of a mask.
void keepLargestIsland(const VoxelGrid& g, Mask& m, Connectivity c = Connectivity::Faces6);
// Keeps the island that holds the seed; throws when the seed is outside the grid or not in
// the mask.
void keepIslandAt(const VoxelGrid& g, Mask& m, glm::ivec3 seed,
                  Connectivity c = Connectivity::Faces6);
// Removes every island smaller than minMm3 cubic millimetres.
void removeSmallIslands(const VoxelGrid& g, Mask& m, double minMm3,
                        Connectivity c = Connectivity::Faces6);

// Fills the holes: background that no face-connected path joins to the grid's border.
void fillHoles(const VoxelGrid& g, Mask& m);

// Grows (mm > 0) or shrinks (mm < 0) the mask by a Euclidean distance in millimetres on the
// grid's (anisotropic) spacing: a voxel joins when its centre lies within |mm| of a mask
// voxel's centre; a mask voxel leaves when a background voxel's centre lies within |mm|.
// The volume's border is not background: shrinking does not eat from the edge.
void applyMargin(const VoxelGrid& g, Mask& m, double mm);

// Smoothing with a kernel of the given diameter in millimetres (per axis: the odd number of
// voxels closest to it, at least 1). Median: majority vote; closing fills gaps and dents
// narrower than the kernel; opening removes spurs and bridges thinner than it.
void medianSmooth(const VoxelGrid& g, Mask& m, double kernelMm);
void closing(const VoxelGrid& g, Mask& m, double kernelMm);
void opening(const VoxelGrid& g, Mask& m, double kernelMm);

// The voxels of one segment's label as a mask.
Mask maskOf(const Segmentation& s, uint8_t label);

// Logical operations of one segment with another: add (union), subtract, intersect. The
// result is written into the target's label as segment_edit.h's setMask does.
enum class LogicalOp { Add, Subtract, Intersect };
// With one label per voxel two segments never overlap: subtracting or intersecting another
// segment matters for masks from other sources (an operation's result, another file), which
// the second form takes.
Mask logical(const Segmentation& s, uint8_t target, uint8_t other, LogicalOp op);
Mask logical(const Segmentation& s, uint8_t target, const Mask& other, LogicalOp op);

}  // namespace voxray
