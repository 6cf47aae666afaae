#pragma once
// INPUT and its flags (the raw layout and the DICOM series, declared in input_flags.h) shared
// by info, render and bench. INPUT db:SERIES_UID (or --db DIR --series UID without INPUT)
// opens a series of the local study database.
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "voxray/io/load.h"

namespace voxray::cli {

struct InputOptions {
  std::string input;                         // empty: the embedded head phantom
  std::map<std::string, std::string> flags;  // --KEY VALUE of inputFlagSpecs() the user gave
  int phantomSize = 256;                     // voxels per axis of the head phantom (no INPUT)
  int level = 0;                             // --level: an OME-Zarr pyramid's level
  std::string db;  // --db: the study database a db:SERIES_UID input (or --series) is found in

  void add(CLI::App& cmd);
  // Loads the volume, showing progress on stderr when it is a terminal.
  Volume load() const;
  LoadOptions loadOptions() const;  // throws Error (Input) for a bad flag
};

}  // namespace voxray::cli
