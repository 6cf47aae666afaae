// Fuzzes what a user's file goes through: listing, then import, of one file, and the import
// of the same bytes handed over as a PACS retrieval hands them (parsed from memory). The only
// acceptable failure is voxray::Error; anything else (crash, other exception, sanitizer
// report) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scratch_file.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = voxray::fuzz::scratchPath("dicom");
  if (!voxray::fuzz::writeScratch(path, data, size)) return 0;
  try {
    voxray::listDicomSeries(path);
  } catch (const voxray::Error&) {
  }
  try {
    voxray::importDicom(path);
  } catch (const voxray::Error&) {
  }
  try {
    voxray::DicomImport fed;
    fed.add(path, std::string(reinterpret_cast<const char*>(data), size));
    fed.finish(path);
  } catch (const voxray::Error&) {
  }
  return 0;
}
