#pragma once
// SUVpeak of segments (issue 36) for the Segments panel's statistics, their CSV, `voxray-cli
// segment`'s statistics and the SR: the 1 cm³ sphere of mask_peak.h, on the volume when it
// has an SUV scale (a PET with the attributes SUV needs), else on the fused overlay when that
// has one (the segment taken onto the overlay's own grid, nearest voxel). Qt-free.
#include <string>
#include <vector>

#include "no_qt.h"
#include "voxray/io/segment_stats.h"
#include "voxray/io/segmentation.h"
#include "voxray/io/volume.h"

namespace voxray {

// Fills each of STATS' suvPeak (SUVbw), peakOf (OVERLAYNAME for the overlay's, "" for the
// volume's) and peakNote (why there is none: a segment too small for the sphere). Without an
// SUV scale in V or OVERLAY (null: none) it leaves them as they are. S is on V's grid.
void addSuvPeaks(std::vector<SegmentStats>& stats, const Segmentation& s, const Volume& v,
                 const Volume* overlay = nullptr, const std::string& overlayName = "");

}  // namespace voxray
