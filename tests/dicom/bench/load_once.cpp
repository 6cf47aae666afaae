// Loads one DICOM input once and prints seconds and volume size: run under
// /usr/bin/time -v for the peak RSS of exactly one import. With --checksum, also the
// FNV-1a hash of the voxels and the rescale (after the timing), to compare two builds.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

int main(int argc, char** argv) {
  const bool checksum = argc > 2 && std::strcmp(argv[2], "--checksum") == 0;
  if (argc < 2) {
    std::fprintf(stderr, "usage: voxray_dicom_load_once PATH [--checksum]\n");
    return 2;
  }
  try {
    auto t0 = std::chrono::steady_clock::now();
    voxray::Volume v = voxray::importDicom(argv[1]);
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%.3f s, %dx%dx%d, %.1f MB\n", s, v.dims.x, v.dims.y, v.dims.z,
                double(v.byteSize()) / (1 << 20));
    if (checksum) {
      uint64_t h = 14695981039346656037ull;
      for (int16_t x : v.voxels) h = (h ^ uint16_t(x)) * 1099511628211ull;
      std::printf("voxels fnv1a %016llx, slope %g, intercept %g\n", (unsigned long long)h, v.slope,
                  v.intercept);
    }
  } catch (const voxray::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
