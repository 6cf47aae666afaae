#pragma once
// render --overlay FILE (issue 36): a second volume (PET on CT, ...) fused into dvr frames
// (Raycaster::setOverlay), with its table from --overlay-tf (a preset name or a preset
// JSON file) or from --overlay-window and --overlay-colormap, and --overlay-opacity; a 4D
// overlay's time point from --overlay-time or, as the workstation's overlay follows its time
// slider, the study's when both have as many time points (ui/study/time_follow.h).
#include <optional>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

#include "voxray/engine/transfer_function.h"
#include "voxray/io/volume.h"

namespace voxray::cli {

struct OverlayOption {
  std::string path, tf, window, colormap = "hot-iron";
  std::optional<double> opacity;
  std::optional<int> time;

  void add(CLI::App& cmd);
  // The overlay and its table, at the time point that goes with STUDY; none without
  // --overlay. Throws Error (Input) naming the flag that is wrong.
  std::optional<std::pair<Volume, TransferFunction>> load(const Volume& study) const;
};

}  // namespace voxray::cli
