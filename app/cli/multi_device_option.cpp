#include "multi_device_option.h"

#include <sstream>

#include "voxray/engine/multi_device.h"
#include "voxray/io/error.h"

namespace voxray::cli {

void MultiDeviceOption::add(CLI::App& cmd) {
  cmd.add_option("--split", split,
                 "render each frame on this many devices, the volume split along z between "
                 "them and the images composited (sort-last): --devices' devices, or the "
                 "--device one split into equal sub-devices (a CPU) or shared")
      ->check(CLI::Range(1, 64));
  cmd.add_option("--devices", devices,
                 "comma-separated devices for --split, one part each (e.g. 0,1; "
                 "'voxray-cli devices' lists them)");
  cmd.add_option("--device-budget-mib", budgetMib,
                 "with --split/--devices: the most each device may hold of the volume (its "
                 "range and apron); a range over it is an error that says so");
  cmd.add_option("--composite", composite,
                 "with --split/--devices: where the parts' images are composited: device "
                 "(the first device; the others' images come to it in half floats, only the "
                 "frame comes back) or host (every part's float image comes back)")
      ->check(CLI::IsMember({"device", "host"}));
  cmd.add_option("--bands", bands,
                 "with --split/--devices and the device composite: bands of rows each frame is "
                 "rendered and composited in, so that transfers overlap the kernels (0: by the "
                 "height, about 256 rows a band, at most 8)")
      ->check(CLI::Range(0, 64));
  cmd.add_flag("--balance", balance,
               "with --split/--devices: each device holds the whole volume where they all can, "
               "and the z ranges move between frames so that their kernel times even out");
}

MultiDeviceOptions::Composite MultiDeviceOption::compositeWhere() const {
  return composite == "host" ? MultiDeviceOptions::Composite::Host
                             : MultiDeviceOptions::Composite::Device;
}

std::vector<std::unique_ptr<ClContext>> MultiDeviceOption::contexts(
    const std::string& device) const {
  std::vector<std::string> list;
  std::stringstream ss(devices);
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) list.push_back(item);
  if (list.empty()) return splitDevice(device, split > 0 ? split : 1);
  if (split > 0 && split != int(list.size()))
    throw inputError("--split " + std::to_string(split) + " does not match the " +
                     std::to_string(list.size()) +
                     " devices of --devices: give one part per device, or leave --split out");
  std::vector<std::unique_ptr<ClContext>> out;
  for (const std::string& d : list) {
    try {
      out.push_back(std::make_unique<ClContext>(d));
    } catch (const Error& e) {
      // ClContext names --device; the user gave this one in --devices.
      std::string m = e.what();
      if (m.rfind("--device: ", 0) == 0) m = m.substr(10);
      throw Error(e.kind(), "--devices " + devices + ": " + m);
    }
  }
  return out;
}

}  // namespace voxray::cli
