// Fuzzes the raw importer: the first bytes choose a layout (sample type, byte order, X, Y,
// header bytes, single file or slice stack, a slice pattern), the rest is the data. Only
// voxray::Error may come out; a volume that loads must have the layout's dimensions.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "scratch_file.h"
#include "voxray/io/error.h"
#include "voxray/io/raw_import.h"

namespace {

constexpr size_t kLayoutBytes = 8;

void check(bool ok) {
  if (!ok) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace fs = std::filesystem;
  if (size < kLayoutBytes) return 0;
  static const std::string dir = voxray::fuzz::scratchPath("raw");
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);

  voxray::RawLayout l;
  l.type = voxray::SampleType(data[0] % 4);
  l.order = data[1] & 1 ? voxray::ByteOrder::Big : voxray::ByteOrder::Little;
  l.dims = {1 + data[2] % 32, 1 + data[3] % 32, (data[1] >> 1) % 4};  // Z 0: count slices
  l.headerBytes = data[4] % 16;
  l.slope = data[5] & 0x80 ? -0.5 : 1.0;
  const int mode = data[6] % 3, slices = 1 + data[7] % 4;
  const uint8_t* body = data + kLayoutBytes;
  const size_t bodySize = size - kLayoutBytes;

  std::string input;
  if (mode == 0) {  // one raw file
    input = dir + "/volume.raw";
    voxray::fuzz::writeScratch(input, body, bodySize);
  } else {  // a stack of SLICES files: a folder (mode 1) or a pattern with a range (mode 2)
    const size_t part = bodySize / size_t(slices);
    for (int k = 0; k < slices; ++k)
      voxray::fuzz::writeScratch(dir + "/s." + std::to_string(k + 1), body + size_t(k) * part,
                                 k + 1 == slices ? bodySize - size_t(k) * part : part);
    input = mode == 1 ? dir : dir + "/s.%d";
    if (mode == 2 || data[7] & 0x80) l.range = std::pair{1 + data[5] % 3, 1 + data[5] % 5};
  }
  try {
    const voxray::Volume v = voxray::importRaw(input, l);
    check(v.dims.x == l.dims.x && v.dims.y == l.dims.y);
    check(l.dims.z == 0 || v.dims.z == l.dims.z);
    check(v.voxels.size() == size_t(v.dims.x) * size_t(v.dims.y) * size_t(v.dims.z));
  } catch (const voxray::Error&) {
  }
  return 0;
}
