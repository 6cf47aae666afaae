#include "file_kind.h"

#include <filesystem>
#include <system_error>

#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray::detail {

void refuseSpecialFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);
  const char* kind = nullptr;
  switch (s.type()) {
    case fs::file_type::fifo:
      kind = "a FIFO (named pipe)";
      break;
    case fs::file_type::socket:
      kind = "a socket";
      break;
    case fs::file_type::block:
    case fs::file_type::character:
      kind = "a device";
      break;
    default:
      return;
  }
  throw inputError(path + ": is " + std::string(kind) +
                   ", not a regular file or folder; save the data to a file and open that");
}

}  // namespace voxray::detail
