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

Placement placeInFolder(const std::string& folder, const std::string& candidate,
                        std::string* resolved) {
  std::error_code ec;
  const fs::path file = fs::canonical(candidate, ec);
  if (ec) return Placement::Missing;
  if (resolved) *resolved = file.string();
  const fs::path root = fs::canonical(folder, ec);
  if (ec) return Placement::Missing;
  // Component by component: "/data/ab" is not inside "/data/a".
  auto r = root.begin(), f = file.begin();
  for (; r != root.end() && !r->empty(); ++r, ++f)
    if (f == file.end() || *f != *r) return Placement::Outside;
  if (f == file.end()) return Placement::NotRegular;  // the folder itself
  return fs::is_regular_file(file, ec) ? Placement::Inside : Placement::NotRegular;
}

}  // namespace voxray::detail
