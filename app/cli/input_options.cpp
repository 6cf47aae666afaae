#include "input_options.h"

#include "progress.h"
#include "spec_options.h"
#include "voxray/engine/input_flags.h"
#include "voxray/io/phantom.h"

namespace voxray::cli {

void InputOptions::add(CLI::App& cmd) {
  cmd.add_option("input", input,
                 "DICOM file or folder, raw slice folder, printf pattern or raw file "
                 "(none: the embedded head phantom)");
  addSpecOptions(cmd, inputFlagSpecs(), flags);
  cmd.add_option("--phantom-size", phantomSize,
                 "no INPUT: voxels per axis of the head phantom (1024: a 2 GiB volume)")
      ->check(CLI::Range(2, 1024));
}

LoadOptions InputOptions::loadOptions() const { return loadOptionsFromFlags(flags); }

Volume InputOptions::load() const {
  LoadOptions o = loadOptions();
  if (input.empty()) return makeHeadPhantom(phantomSize);
  o.progress = terminalProgress("loading");
  return loadVolume(input, o);
}

}  // namespace voxray::cli
