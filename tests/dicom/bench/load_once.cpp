// Loads one DICOM input once and prints seconds and volume size: run under
// /usr/bin/time -v for the peak RSS of exactly one import.
#include <chrono>
#include <cstdio>

#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: voxray_dicom_load_once PATH\n");
    return 2;
  }
  try {
    auto t0 = std::chrono::steady_clock::now();
    voxray::Volume v = voxray::importDicom(argv[1]);
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%.3f s, %dx%dx%d, %.1f MB\n", s, v.dims.x, v.dims.y, v.dims.z,
                double(v.byteSize()) / (1 << 20));
  } catch (const voxray::Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
