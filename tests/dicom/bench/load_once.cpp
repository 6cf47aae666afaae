// Loads one DICOM input once and prints seconds and volume size: run under
// /usr/bin/time -v for the peak RSS of exactly one import. With --checksum, also the
// FNV-1a hash of the voxels and the rescale (after the timing), to compare two builds.
// With --fed, the folder's files are read into memory first (not timed) and handed to a
// DicomImport as a PACS retrieval hands them over; the time and CPU are then those of
// feeding and finishing it (the import's own share of a retrieval, without the network).
#include <sys/resource.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "folder_bytes.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

namespace {

double cpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

}  // namespace

int main(int argc, char** argv) {
  bool checksum = false, fed = false;
  for (int i = 2; i < argc; ++i) {
    checksum |= std::strcmp(argv[i], "--checksum") == 0;
    fed |= std::strcmp(argv[i], "--fed") == 0;
  }
  if (argc < 2) {
    std::fprintf(stderr, "usage: voxray_dicom_load_once PATH [--checksum] [--fed]\n");
    return 2;
  }
  try {
    auto files =
        fed ? voxray::test::filesOf(argv[1]) : std::vector<std::pair<std::string, std::string>>{};
    const double cpu0 = cpuSeconds();
    auto t0 = std::chrono::steady_clock::now();
    voxray::Volume v;
    if (fed) {
      voxray::DicomImport import;
      for (auto& [path, bytes] : files) import.add(path, std::move(bytes));
      v = import.finish(argv[1]);
    } else {
      v = voxray::importDicom(argv[1]);
    }
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%.3f s (CPU %.3f s), %dx%dx%d, %.1f MB\n", s, cpuSeconds() - cpu0, v.dims.x,
                v.dims.y, v.dims.z, double(v.byteSize()) / (1 << 20));
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
