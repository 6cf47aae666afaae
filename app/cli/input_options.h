#pragma once
// INPUT and its flags (the raw layout and the DICOM series, declared in input_flags.h) shared
// by info, render and bench.
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "voxray/io/load.h"

namespace voxray::cli {

struct InputOptions {
  std::string input;                         // empty: the embedded head phantom
  std::map<std::string, std::string> flags;  // --KEY VALUE of inputFlagSpecs() the user gave
  int phantomSize = 256;                     // voxels per axis of the head phantom (no INPUT)

  void add(CLI::App& cmd);
  // Loads the volume, showing progress on stderr when it is a terminal.
  Volume load() const;
  LoadOptions loadOptions() const;  // throws Error (Input) for a bad flag
};

}  // namespace voxray::cli
