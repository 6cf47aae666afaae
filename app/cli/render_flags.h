#pragma once
// Every declared render parameter as a --flag (from renderParamSpecs()), shared by render
// and bench.
#include <map>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "voxray/engine/render_params.h"

namespace voxray::cli {

struct RenderFlags {
  std::map<std::string, std::string> given;  // --KEY VALUE the user wrote
  void add(CLI::App& cmd, const std::vector<std::string>& skip = {});
  // applyRenderValues: a preset brings its mode, iso range and window; flags given win.
  RenderParams params() const;
};

}  // namespace voxray::cli
