#pragma once
// Declared parameters (render_params.h, input_flags.h) as CLI11 options: each --KEY VALUE the
// user writes lands in GIVEN, to be read by the list's own parser.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace voxray::cli {

template <class Spec>
void addSpecOptions(CLI::App& cmd, const std::vector<Spec>& specs,
                    std::map<std::string, std::string>& given,
                    const std::vector<std::string>& skip = {}) {
  for (const auto& spec : specs) {
    if (std::find(skip.begin(), skip.end(), spec.key) != skip.end()) continue;
    std::string key = spec.key;
    cmd.add_option_function<std::string>(
           "--" + key, [&given, key](const std::string& v) { given[key] = v; }, spec.help)
        ->type_name(spec.valueHint);
  }
}

}  // namespace voxray::cli
