#include <iostream>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "json_text.h"
#include "voxray/engine/cl_context.h"

namespace voxray::cli {

Run addDevicesCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("devices", "List OpenCL platforms and devices");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "machine-readable output");
  return [json] {
    auto devices = listDevices();
    if (*json) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& d : devices)
        out.push_back({{"index", d.index},
                       {"platform", d.platform},
                       {"name", d.name},
                       {"type", d.isGpu ? "gpu" : "cpu"},
                       {"version", d.version},
                       {"global_mem_bytes", d.globalMemBytes},
                       {"max_alloc_bytes", d.maxAllocBytes},
                       {"image_support", d.imageSupport},
                       {"compute_units", d.computeUnits}});
      std::cout << jsonText(out) << "\n";
      return 0;
    }
    for (const auto& d : devices) {
      std::cout << d.index << ": " << d.name << " (" << (d.isGpu ? "GPU" : "CPU") << ", "
                << d.platform << ", " << d.version << ")\n"
                << "   " << d.computeUnits << " compute units, " << (d.globalMemBytes >> 20)
                << " MiB memory, largest allocation " << (d.maxAllocBytes >> 20) << " MiB, images "
                << (d.imageSupport ? "yes" : "no") << "\n";
    }
    return 0;
  };
}

}  // namespace voxray::cli
