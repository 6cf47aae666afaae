// Fuzzes the research-format readers (NIfTI-1/2, NRRD, MetaImage) through importVolumeFile:
// the first byte picks the file name ending, the rest is the file. A detached header (.nhdr,
// .mhd) finds a fixed 4 KiB data.raw beside it. Only voxray::Error may come out; a volume that
// loads has as many voxels as its dimensions say, and finite, positive spacing.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scratch_file.h"
#include "voxray/io/error.h"
#include "voxray/io/volume_file.h"

namespace {

void check(bool ok) {
  if (!ok) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace fs = std::filesystem;
  if (size < 1) return 0;
  static const char* const kEndings[] = {".nii", ".nrrd", ".nhdr", ".mha", ".mhd"};
  static const std::string dir = voxray::fuzz::scratchPath("volume_file");
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  const std::string path = dir + "/volume" + kEndings[data[0] % 5];
  voxray::fuzz::writeScratch(path, data + 1, size - 1);
  std::vector<uint8_t> detached(4096);
  for (size_t i = 0; i < detached.size(); ++i) detached[i] = uint8_t(i * 37u);
  voxray::fuzz::writeScratch(dir + "/data.raw", detached.data(), detached.size());
  try {
    const voxray::Volume v = voxray::importVolumeFile(path);
    check(v.voxels.size() == v.voxelCount());
    for (int a = 0; a < 3; ++a) check(std::isfinite(v.spacingMm[a]) && v.spacingMm[a] > 0.0);
  } catch (const voxray::Error&) {
  }
  return 0;
}
