#pragma once
// The numbers of a segment: voxels, volume, and the volume's values inside it.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "voxray/io/segmentation.h"

namespace voxray {

struct SegmentStats {
  uint8_t label = 0;
  std::string name;
  size_t voxels = 0;
  double volumeMm3 = 0.0;
  double volumeMl = 0.0;
  std::string unit = "HU";
  // The volume's physical values inside; none for an empty segment.
  std::optional<double> mean, sd, min, max, median;
  // The surface mesh's area, filled by whoever makes the mesh; none until then.
  std::optional<double> surfaceMm2;
  // SUVpeak in SUVbw (the 1 cm³ sphere, voxray/engine/mask_peak.h), filled where the values
  // have an SUV scale (ui/study/segment_peak.h); PEAKOF: the overlay's name when it is the
  // fused overlay's, "" the volume's; PEAKNOTE: why there is none (a segment too small).
  std::optional<double> suvPeak;
  std::string peakOf, peakNote;
};

// Throws an input Error when the segmentation is not on the volume's grid.
SegmentStats segmentStats(const Segmentation& s, const Volume& v, uint8_t label);
std::vector<SegmentStats> allSegmentStats(const Segmentation& s, const Volume& v);

// A header line and one line per segment; empty values for what has none.
std::string statsCsv(const std::vector<SegmentStats>& stats);
// {"segments": [{"label": 1, "name": ..., "voxels": ..., "volume_mm3": ..., "volume_ml": ...,
// "unit": "HU", "mean": ..., "sd", "min", "max", "median", "surface_mm2": null,
// "suv_peak": null}]}; "suv_peak_of" and "suv_peak_note" only when set.
std::string statsJson(const std::vector<SegmentStats>& stats);

}  // namespace voxray
