// Fuzzes what a user's file goes through: listing, then import, of one file. The only
// acceptable failure is voxray::Error; anything else (crash, other exception, sanitizer
// report) is a bug.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // DCMTK reads files: one scratch file per fuzzing process, in memory-backed /dev/shm.
  static const std::string path = "/dev/shm/voxray-dicom-fuzz-" + std::to_string(getpid());
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    voxray::listDicomSeries(path);
  } catch (const voxray::Error&) {
  }
  try {
    voxray::importDicom(path);
  } catch (const voxray::Error&) {
  }
  return 0;
}
