#pragma once
// The peak of a 3D region (a segment's voxels): roi_peak.h's 1 cm³ sphere (PERCIST 1.0, QIBA
// SUVpeak) with the same rules in three dimensions. The sphere's centre lies on the centre of
// a voxel of the region, every voxel whose centre lies within the radius of it is in the
// region (the sphere fits the segment, as a plane ROI's prism must hold it), and the whole
// sphere lies inside the volume. Ties go to the first centre in voxel order; each voxel
// counts by the fraction of its cell inside the sphere.
#include <cstdint>
#include <vector>

#include "voxray/engine/roi_peak.h"
#include "voxray/io/segmentation.h"

namespace voxray {

// What the statistics say instead of a SUVpeak when no centre has room.
constexpr const char* kNoRoomForPeakInSegment =
    "no room for a 1 cm3 sphere inside the segment (it needs to be at least 12.4 mm across, "
    "away from the volume's edges)";

// LABELS: one per voxel of V (V's grid, i fastest); the region is where it equals LABEL.
// Throws Error (Input) when LABELS is not V's size or the radius is no positive finite number.
RoiPeak maskPeak(const Volume& v, const std::vector<uint8_t>& labels, uint8_t label,
                 double radiusMm = kPeakSphereRadiusMm);

// The region LABEL of LABELS (on FROM's grid) on ONTO's grid: each voxel of ONTO is in it when
// the voxel of FROM nearest its centre's patient point (LPS mm) is; 1 inside, 0 outside. For
// a segment drawn on a CT, its voxels on the PET overlay's own grid.
std::vector<uint8_t> maskOnGrid(const VoxelGrid& from, const std::vector<uint8_t>& labels,
                                uint8_t label, const Volume& onto);

}  // namespace voxray
