#include <iostream>

#include "commands.h"
#include "voxray/engine/transfer_function.h"

namespace voxray::cli {

Run addPresetsCommand(CLI::App& app) {
  app.add_subcommand("presets", "List the transfer-function presets in resources/presets");
  return [] {
    for (const auto& p : builtinPresets())
      std::cout << p.name << " (" << p.mode << "): " << p.description << "\n";
    return 0;
  };
}

}  // namespace voxray::cli
