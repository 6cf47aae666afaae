#pragma once
// The peak of a region: the highest mean value in a sphere of 1 cm³ (PERCIST 1.0, Wahl et al.
// 2009; QIBA's SUVpeak), for a PET's ROI read in SUV. Qt-free; shared by the workstation's ROI
// readout and `voxray-cli measure --roi`.
//
// The rules (docs/architecture.md names them too):
// - Placement: the sphere's centre lies on the centre of a voxel of the ROI (the ROI's own
//   pixel rule, roiStats). A plane ROI is taken as the prism it sweeps along its normal, and
//   the sphere must fit in it: every voxel of the ROI's plane whose centre lies within the
//   radius of the sphere's centre is a pixel of the ROI. The whole sphere must also lie inside
//   the volume (no voxel outside it is guessed). A ROI without such a centre has no peak. The
//   footprint is counted in voxels, as the ROI is: with 4 mm voxels a 3 x 3 voxel square (its
//   cells 12 mm across) has room; with 2 mm voxels the square needs 7 x 7.
// - Ties (a hot voxel wholly inside several spheres) go to the first centre in slice order.
// - Weighting: each voxel counts by the fraction of its cell inside the sphere (computed once
//   for the grid by sub-sampling a cell's boundary-crossing voxels 16 x 16 x 16 times; a cell
//   wholly inside counts 1). The peak is the weighted mean sum(w v) / sum(w).
#include <cstddef>
#include <optional>

#include <glm/glm.hpp>

#include "voxray/engine/measure.h"

namespace voxray {

// The radius of a sphere of 1 cm³: (3 * 1000 mm³ / (4 pi))^(1/3).
constexpr double kPeakSphereRadiusMm = 6.2035049089940;

struct RoiPeak {
  std::optional<double> mean;  // physical units (SUV: times the volume's factor); none: no room
  glm::ivec3 centre{-1};       // the voxel at the best sphere's centre
  size_t centres = 0;          // the ROI's voxels where the sphere fits
  double sphereMm3 = 0.0;      // the weights' sum times a voxel's volume (about 1000 mm³)
};

// What a readout says instead of a number when no centre has room.
constexpr const char* kNoRoomForPeak =
    "no room for a 1 cm3 sphere: draw the ROI at least 12.4 mm across, away from the "
    "volume's edges";

// Throws Error (Input) for a bad plane axis or a radius that is not a positive finite number.
RoiPeak roiPeak(const Volume& v, const PlaneRoi& roi, double radiusMm = kPeakSphereRadiusMm);

}  // namespace voxray
