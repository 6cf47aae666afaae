#pragma once
// --memory-budget MIB (render, bench): the volume on one device out of core
// (voxray/engine/out_of_core.h, issue 38 part 2), an OME-Zarr INPUT read on demand.
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include <CLI/CLI.hpp>
#include "bench_run.h"
#include "input_options.h"
#include "voxray/engine/render_params.h"
#include "voxray/engine/slab_source.h"

namespace voxray::cli {

struct OutOfCoreOption {
  size_t budgetMib = 0;
  int partSlices = 0;
  std::string upload = "auto";  // --ooc-upload: auto, direct or pinned (OutOfCoreOptions::Upload)
  std::string reuse = "on";     // --ooc-reuse: OutOfCoreOptions::reuseDeviceMemory

  void add(CLI::App& cmd);
  bool active() const { return budgetMib > 0; }
};

// INPUT's source: an OME-Zarr's level 0 read on demand (only --level 0: the full volume), else
// the loaded volume, held in HELD.
std::unique_ptr<SlabSource> openSlabSource(const InputOptions& input, std::optional<Volume>& held);

struct OutOfCoreRun {
  std::string device, storage = "auto";
  bool ess = true;
  bool json = false;
  bool firstOnly = false;  // bench --first-image: the first image's times, no other frame
};

// The converged frame of SOURCE into OUTPUT; a summary on stderr.
int renderOutOfCore(const OutOfCoreOption& option, SlabSource& source, const RenderParams& p,
                    const OutOfCoreRun& run, const std::string& output);

// Over the orbit: preview frames (what a drag shows, uploading nothing) and converged frames,
// their medians, the parts held and the bytes uploaded per converged frame, the time to the
// first image and the peak resident memory.
void benchOutOfCore(const OutOfCoreOption& option, SlabSource& source, const std::string& name,
                    const RenderParams& p, const OutOfCoreRun& run, const BenchRun& bench,
                    std::ostream& out);

}  // namespace voxray::cli
