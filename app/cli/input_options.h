#pragma once
// INPUT and the raw-layout flags shared by info, render and bench.
#include <string>

#include <CLI/CLI.hpp>

#include "voxray/io/load.h"

namespace voxray::cli {

struct InputOptions {
  std::string input;  // empty: the embedded head phantom
  std::string rawDims, rawType = "i16", rawEndian = "little", rawSpacing, rawRescale, rawRange,
                       rawAxes;
  size_t rawOffset = 0;
  std::string series;
  int phantomSize = 256;  // voxels per axis of the head phantom (no INPUT)

  void add(CLI::App& cmd);
  // Loads the volume, showing progress on stderr when it is a terminal.
  Volume load() const;
  LoadOptions loadOptions() const;
};

}  // namespace voxray::cli
