#pragma once
// One entry point for every input the user can open: a DICOM file/folder/DICOMDIR, or a
// raw slice stack / raw file described by RawLayout. An empty input gives the embedded
// head phantom. The CLI and the workstation both open volumes through here.
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "voxray/io/raw_import.h"
#include "voxray/io/volume.h"

namespace voxray {

struct LoadOptions {
  std::optional<RawLayout> raw;  // set: read INPUT as raw data with this layout
  std::string series;            // DICOM: series number or UID; empty = the default choice
  // 4D (DICOM, NIfTI): the time point to load, 0-based; none: the first, or the one --series
  // names.
  std::optional<int> timePoint;
  int level = 0;  // OME-Zarr: the pyramid level, 0 (full resolution) up to the coarsest
  // Progress 0..1 and a message; called from worker threads. May be empty.
  std::function<void(double, const std::string&)> progress;
  const std::atomic<bool>* cancel = nullptr;  // set to true to abandon the load
};

// Throws Error (Input) saying what is wrong with which file and what to do.
Volume loadVolume(const std::string& input, const LoadOptions& options = {});

// Every time point of a 4D input (options.timePoint is ignored), in time order; one volume
// for a 3D input. Throws Error (Input) as loadVolume does.
std::vector<Volume> loadVolumeSeries(const std::string& input, const LoadOptions& options = {});

}  // namespace voxray
