// Fuzzes the session reader (ui/study/session*.cpp): the input is a session file's text. Only
// voxray::Error may come out, and a session that reads must write out as JSON that reads back
// (what Voxray writes, Voxray must read).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "scratch_file.h"
#include "session.h"
#include "voxray/io/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // A folder of its own: the reader looks for the session's data beside it.
  static const std::string path = voxray::fuzz::scratchPath("study.json");
  const std::string text(reinterpret_cast<const char*>(data), size);
  voxray::SessionRead read;
  try {
    read = voxray::sessionFromJson(text, path);
  } catch (const voxray::Error&) {
    return 0;
  }
  const std::string written = voxray::sessionToJson(read.session, path);
  try {
    voxray::sessionFromJson(written, path);
  } catch (const voxray::Error& e) {
    std::fprintf(stderr, "a written session does not read back (%s):\n%s", e.what(),
                 written.c_str());
    __builtin_trap();
  }
  return 0;
}
