#pragma once
// --split N and --devices LIST (render, bench): one frame over several OpenCL devices,
// sort-last (voxray/engine/multi_device.h).
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include "voxray/engine/cl_context.h"
#include "voxray/engine/multi_device.h"

namespace voxray::cli {

struct MultiDeviceOption {
  int split = 0;        // parts; 0: one per --devices entry (or one device, no split)
  std::string devices;  // comma-separated device numbers or names (ClContext's selectors)
  size_t budgetMib = 0;
  int bands = 0;                     // --bands (MultiDeviceOptions::bands)
  bool balance = false;              // --balance (MultiDeviceOptions::balance)
  std::string composite = "device";  // --composite: device or host (MultiDeviceOptions)

  void add(CLI::App& cmd);
  bool active() const { return split > 0 || !devices.empty(); }  // --split 1: one part
  // The contexts of the parts: --devices' devices (part k on entry k), or the --device one
  // (DEVICE) split into --split equal sub-devices where it can be (a CPU under PoCL), else
  // --split contexts on it. Throws Error (Input) for a --split that does not match --devices.
  std::vector<std::unique_ptr<ClContext>> contexts(const std::string& device) const;
  // --composite as MultiDeviceOptions' Composite.
  MultiDeviceOptions::Composite compositeWhere() const;
};

}  // namespace voxray::cli
