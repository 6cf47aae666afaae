#pragma once
// bench --split / --devices: one frame over several devices (voxray/engine/multi_device.h),
// timed over the orbit like a bench case, with each device's kernel time and the time its
// image reached the host, and the host's composite alone (medians).
#include <ostream>
#include <string>

#include "bench_run.h"
#include "voxray/engine/multi_device.h"

namespace voxray::cli {

struct MultiDeviceRow {
  std::string input, size, mode;
  int parts = 0;
  double medianMs = 0, minMs = 0, maxMs = 0, fps = 0, compositeMs = 0;
  bool deviceComposite = false;  // composited on the first device (else the host)
  int hostDiff = -1;  // device composite: the largest difference from the host's (levels)
  std::vector<PartStats> devices;  // per part: medians of kernelMs and readyMs, its range
};

MultiDeviceRow benchMultiDevice(MultiDeviceRenderer& r, RenderParams p, const BenchRun& run);
void printMultiDeviceRow(const MultiDeviceRow& row, bool json, std::ostream& out);

}  // namespace voxray::cli
