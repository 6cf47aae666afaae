#pragma once
// Every declared render parameter as a --flag (from renderParamSpecs()), shared by render,
// bench, movie and accuracy, and --tf-file, a transfer function from a file.
#include <map>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "voxray/engine/render_params.h"

namespace voxray::cli {

struct RenderFlags {
  std::map<std::string, std::string> given;  // --KEY VALUE the user wrote
  std::string tfFile;                        // --tf-file: Voxray JSON or Slicer .vp
  void add(CLI::App& cmd, const std::vector<std::string>& skip = {});
  // Onto P: the --tf-file's table, mode, shading and sampling, then the flags given (a preset
  // brings its mode, iso range and window; flags given win). Throws Error (Input) for a bad
  // file, and when --tf-file comes with --preset or --tf, which it would replace.
  void applyTo(RenderParams& p) const;
  RenderParams params() const;
};

}  // namespace voxray::cli
