#include "render_flags.h"

#include "spec_options.h"

namespace voxray::cli {

void RenderFlags::add(CLI::App& cmd, const std::vector<std::string>& skip) {
  addSpecOptions(cmd, renderParamSpecs(), given, skip);
}

RenderParams RenderFlags::params() const {
  RenderParams p;
  applyRenderValues(p, given);
  return p;
}

}  // namespace voxray::cli
