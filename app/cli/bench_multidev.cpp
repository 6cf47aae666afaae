#include "bench_multidev.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "voxray/engine/orbit.h"
#include "voxray/io/statistics.h"

namespace voxray::cli {

MultiDeviceRow benchMultiDevice(MultiDeviceRenderer& r, RenderParams p, const BenchRun& run) {
  Image img;
  std::vector<double> wall, composite;
  std::vector<std::vector<double>> kernel(size_t(r.partCount())), ready(kernel.size());
  MultiDeviceRow row;
  for (int i = -run.warmup; i < run.frames; ++i) {
    orbitCamera(p.camera, run.orbit, std::max(i, 0), run.frames);
    MultiDeviceStats s;
    r.render(p, img, &s);
    if (i < 0) continue;
    wall.push_back(s.totalMs);
    composite.push_back(s.compositeMs);
    for (size_t k = 0; k < s.parts.size(); ++k) {
      kernel[k].push_back(s.parts[k].kernelMs);
      ready[k].push_back(s.parts[k].readyMs);
    }
    row.devices = s.parts;
    row.deviceComposite = s.deviceComposite;
  }
  if (row.deviceComposite) {
    // The orbit's first frame composited on the host too: the largest difference, in 8-bit
    // levels (half floats: at most one; multi_device.h).
    orbitCamera(p.camera, run.orbit, 0, run.frames);
    Image host;
    r.render(p, img);
    r.setComposite(MultiDeviceOptions::Composite::Host);
    r.render(p, host);
    r.setComposite(MultiDeviceOptions::Composite::Device);
    row.hostDiff = 0;
    for (size_t i = 0; i < img.rgba.size() && i < host.rgba.size(); ++i)
      row.hostDiff = std::max(row.hostDiff, std::abs(int(img.rgba[i]) - int(host.rgba[i])));
  }
  row.size = std::to_string(p.width) + "x" + std::to_string(p.height);
  row.mode = toString(p.mode);
  row.parts = r.partCount();
  row.medianMs = median(wall);
  row.minMs = *std::min_element(wall.begin(), wall.end());
  row.maxMs = *std::max_element(wall.begin(), wall.end());
  row.fps = 1000.0 / row.medianMs;
  row.compositeMs = median(composite);
  for (size_t k = 0; k < row.devices.size(); ++k) {
    row.devices[k].kernelMs = median(kernel[k]);
    row.devices[k].readyMs = median(ready[k]);
  }
  return row;
}

void printMultiDeviceRow(const MultiDeviceRow& row, bool json, std::ostream& out) {
  if (json) {
    nlohmann::json j = {{"input", row.input},
                        {"size", row.size},
                        {"mode", row.mode},
                        {"parts", row.parts},
                        {"median_ms", row.medianMs},
                        {"min_ms", row.minMs},
                        {"max_ms", row.maxMs},
                        {"fps", row.fps},
                        {"composite_ms", row.compositeMs},
                        {"composite", row.deviceComposite ? "device" : "host"},
                        {"host_composite_diff", row.hostDiff}};
    for (const PartStats& d : row.devices)
      j["devices"].push_back({{"device", d.device},
                              {"first_slice", d.range.first},
                              {"end_slice", d.range.end},
                              {"kernel_ms", d.kernelMs},
                              {"ready_ms", d.readyMs}});
    out << j.dump() << "\n";
    return;
  }
  char line[256];
  std::snprintf(line, sizeof(line),
                "%-12s %-9s %-4s %d parts: median %.2f ms (min %.2f, max %.2f), %.2f fps, "
                "%s composite %.2f ms\n",
                row.input.c_str(), row.size.c_str(), row.mode.c_str(), row.parts, row.medianMs,
                row.minMs, row.maxMs, row.fps, row.deviceComposite ? "device" : "host",
                row.compositeMs);
  out << line;
  for (size_t k = 0; k < row.devices.size(); ++k) {
    const PartStats& d = row.devices[k];
    std::snprintf(line, sizeof(line),
                  "    device %zu: slices %d-%d (held %d-%d): kernel %.2f ms, ready after %.2f "
                  "ms  [%s]\n",
                  k + 1, d.range.first, d.range.end - 1, d.range.storedFirst, d.range.storedEnd - 1,
                  d.kernelMs, d.readyMs, d.device.c_str());
    out << line;
  }
  if (row.hostDiff >= 0) {
    std::snprintf(line, sizeof(line),
                  "    the first frame composited on the host too: largest difference %d "
                  "levels\n",
                  row.hostDiff);
    out << line;
  }
}

}  // namespace voxray::cli
