// Fuzzes the transfer-function readers (issue 35): Voxray's JSON, 3D Slicer's .vp text and
// its presets.xml list. The first byte picks the reader. Anything but a VolumeProperty that
// validates or an Error (Input) is a finding, and what is read must write back and read
// again to the same property.
#include <cstddef>
#include <cstdint>
#include <string>

#include "voxray/engine/volume_property.h"
#include "voxray/io/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 3) {
      case 0: {
        voxray::VolumeProperty vp = voxray::parseVolumePropertyJson(text, "fuzz.json");
        if (!(voxray::parseVolumePropertyJson(voxray::toVolumePropertyJson(vp), "back") == vp))
          __builtin_trap();
        break;
      }
      case 1: {
        voxray::VolumeProperty vp = voxray::parseSlicerVolumeProperty(text, "fuzz.vp");
        voxray::validate(vp, "fuzz.vp");
        (void)voxray::renderTable(vp);
        break;
      }
      default:
        for (const auto& vp : voxray::parseSlicerPresets(text, "fuzz.xml"))
          voxray::validate(vp, "fuzz.xml");
    }
  } catch (const voxray::Error& e) {
    if (e.kind() != voxray::Error::Kind::Input) __builtin_trap();
  }
  return 0;
}
