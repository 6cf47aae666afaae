#pragma once
// What a slice view draws of the segmentation over its image: each visible segment's voxels
// filled in its colour and outlined, and the threshold tool's preview, on the view's plane
// (slice_image.h's PlaneGrid). Every pixel takes the voxel its centre lies in (nearest), so
// turned planes and slabs (their centre plane) show the label map as the acquisition planes do.
#include <cstdint>
#include <vector>

#include "no_qt.h"
#include "voxray/engine/plane_sampler.h"
#include "voxray/io/image.h"
#include "voxray/io/segment_mask.h"
#include "voxray/io/segmentation.h"

namespace voxray {

// The fill's share of a segment's opacity: half, as 3D Slicer's 2D fill, so that the grey
// values under a segment stay readable; the outline takes the whole opacity.
constexpr float kSegmentFillShare = 0.5f;

// The voxel (index into the grid's voxels) each pixel of G lies in, or -1 outside the grid.
std::vector<int64_t> planeVoxels(const VoxelGrid& grid, const PlaneGrid& g);

// RGBA (not premultiplied) of G's size: a visible segment's pixels in its colour, alpha
// opacity * kSegmentFillShare inside and opacity on its outline (a pixel whose 4-neighbour
// in the image shows another label); transparent elsewhere.
Image segmentOverlay(const Segmentation& s, const PlaneGrid& g);

// The threshold's preview: the pixels whose voxel value lies in RANGE, in COLOUR at ALPHA.
Image thresholdOverlay(const Volume& v, const PlaneGrid& g, HuRange range, glm::vec3 colour,
                       float alpha = 0.6f);

}  // namespace voxray
