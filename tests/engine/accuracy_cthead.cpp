#include "accuracy_cthead.h"

#include <filesystem>
#include <memory>

#include "voxray/io/orientation.h"
#include "voxray/io/raw_import.h"

namespace voxray::test {

const Volume* cthead() {
  static std::unique_ptr<Volume> v = [] {
    std::filesystem::path dir = std::filesystem::path(VOXRAY_SHARED_DATA) / "stanford/CThead";
    if (!std::filesystem::is_directory(dir)) return std::unique_ptr<Volume>();
    RawLayout l;  // voxray-cli's --raw-dims 256,256 --raw-type i16 --raw-endian big ...
    l.dims = {256, 256, 0};
    l.type = SampleType::I16;
    l.order = ByteOrder::Big;
    l.spacingMm = {1.0, 1.0, 2.0};
    l.slope = 1.0;
    l.intercept = -1024.0;
    l.direction = directionFromAxesCode("LPI");
    return std::make_unique<Volume>(importRaw(dir.string(), l));
  }();
  return v.get();
}

RenderParams ctheadDvr(int width, int height) {
  RenderParams p;
  p.width = width;
  p.height = height;
  p.mode = Mode::Dvr;
  p.preset = "CT-Bone";
  p.camera.azimuthDeg = 30.0;
  return p;
}

}  // namespace voxray::test
