// Fuzzes the WADO-RS multipart/related splitter (io/pacs/src/multipart.h), the one parser
// Voxray wrote by hand for network input: the first byte chooses the feed size, the rest is
// a body with boundary "XYZ". Only voxray::Error may come out; every part handed over lies
// inside the input, and a body that finishes had its close delimiter.
#include <cstddef>
#include <cstdint>
#include <string>

#include "multipart.h"
#include "voxray/io/error.h"

namespace {

void check(bool ok) {
  if (!ok) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const size_t chunk = size_t(data[0] % 64) + 1;
  const char* body = reinterpret_cast<const char*>(data + 1);
  const size_t bodySize = size - 1;
  size_t partBytes = 0;
  try {
    voxray::pacs::MultipartSplitter splitter(
        "XYZ", [&](const std::string&, std::string content) { partBytes += content.size(); });
    for (size_t at = 0; at < bodySize; at += chunk)
      splitter.feed(body + at, std::min(chunk, bodySize - at));
    splitter.finish();
    check(std::string(body, bodySize).find("--XYZ--") != std::string::npos);
  } catch (const voxray::Error&) {
  }
  check(partBytes <= bodySize);
  try {
    voxray::pacs::multipartBoundary(std::string(body, bodySize));
  } catch (const voxray::Error&) {
  }
  return 0;
}
