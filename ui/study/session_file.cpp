#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "session.h"
#include "voxray/io/error.h"

namespace voxray {

namespace fs = std::filesystem;

namespace {
// A session is a few kilobytes; anything far larger is not one (and is not read whole).
constexpr std::uintmax_t kMaxSessionBytes = 64u << 20;
}  // namespace

SessionRead readSessionFile(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw inputError("session " + path + ": no such file; give the path of a saved session");
  if (fs::file_size(path, ec) > kMaxSessionBytes)
    throw inputError("session " + path + ": too large for a session file (over 64 MiB)");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw inputError("session " + path + ": cannot read the file");
  return sessionFromJson(text.str(), path);
}

void writeSessionFile(const std::string& path, const Session& s, bool replace) {
  const fs::path target(path);
  std::error_code ec;
  if (fs::is_directory(target, ec))
    throw outputError(path + ": this is a folder; give a file name like study.json");
  if (!replace && fs::exists(target, ec))
    throw outputError(path +
                      ": a file of this name exists and is kept; choose another name or "
                      "allow replacing it (voxray-cli: --force)");
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(folder, ec))
    throw outputError(path + ": the folder " + folder.string() + " does not exist");
  const std::string text = sessionToJson(s, path);
  // Readers of PATH see the old session or the new one, never half a file.
  fs::path temporary = target;
  temporary += ".partial" + std::to_string(::getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
      fs::remove(temporary, ec);
      throw outputError(path + ": cannot write the session (disk full or no permission?)");
    }
  }
  fs::rename(temporary, target, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(temporary, ec);
    throw outputError(path + ": cannot replace the file (" + why + ")");
  }
}

}  // namespace voxray
