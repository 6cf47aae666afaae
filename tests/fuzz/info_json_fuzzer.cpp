// Fuzzes `voxray-cli info --json` from the file to the printed text: listing, loading, the
// JSON document and its text. Invariant: the text is JSON that parses again (valid UTF-8
// included), whatever bytes the file's strings held.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "info_json.h"
#include "json_text.h"
#include "scratch_file.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = voxray::fuzz::scratchPath("info.dcm");
  if (!voxray::fuzz::writeScratch(path, data, size)) return 0;
  std::optional<voxray::DicomListing> listing;
  try {
    listing = voxray::listDicomSeries(path);
  } catch (const voxray::Error&) {
  }
  try {
    const voxray::Volume v = voxray::loadVolume(path);
    const std::string text =
        voxray::cli::jsonText(voxray::cli::infoJson(v, listing ? &*listing : nullptr));
    if (!nlohmann::json::accept(text)) __builtin_trap();
  } catch (const voxray::Error&) {
  }
  return 0;
}
