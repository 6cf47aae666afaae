#pragma once
// --labels-raw FILE (render, bench): a label map for label-aware dvr (issue 34,
// Raycaster::setSegmentation), with --segment-mask and --segment-blend from the render flags.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "voxray/io/segmentation.h"

namespace voxray::cli {

struct LabelsOption {
  std::string raw;       // uint8 per voxel, x fastest, then y, then z, on the volume's dims
  std::string file;      // NIfTI, .seg.nrrd or DICOM SEG on the volume (names and colours kept)
  std::string surfaces;  // --segment-surface L,...: labels drawn as smooth surfaces in dvr

  void add(CLI::App& cmd);
  // The segmentation on V's grid, one segment per label the map holds (named "Segment L",
  // coloured from a fixed palette), or the segments of --labels FILE; none without either. Throws
  // Error (Input) naming the file and the size it should have when it does not fit V, or a
  // --segment-surface label that names no segment.
  std::optional<Segmentation> load(const Volume& v) const;
};

}  // namespace voxray::cli
