#include "render_flags.h"

#include <algorithm>

#include "voxray/engine/transfer_function.h"

namespace voxray::cli {

void RenderFlags::add(CLI::App& cmd, const std::vector<std::string>& skip) {
  for (const auto& spec : renderParamSpecs()) {
    if (std::find(skip.begin(), skip.end(), spec.key) != skip.end()) continue;
    std::string key = spec.key;
    cmd.add_option_function<std::string>(
           "--" + key, [this, key](const std::string& v) { given[key] = v; }, spec.help)
        ->type_name(spec.valueHint);
  }
}

RenderParams RenderFlags::params() const {
  RenderParams p;
  if (auto it = given.find("preset"); it != given.end()) applyPreset(p, findPreset(it->second));
  for (const auto& spec : renderParamSpecs()) {
    auto it = given.find(spec.key);
    if (it != given.end()) spec.parse(p, it->second);
  }
  return p;
}

}  // namespace voxray::cli
