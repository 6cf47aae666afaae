#include "export_target.h"

#include <filesystem>

namespace voxray {

std::string withImageSuffix(const std::string& path) {
  if (path.empty() || std::filesystem::path(path).has_extension()) return path;
  return path + ".png";
}

std::optional<std::string> resolveExportTarget(const std::string& chosen,
                                               const ConfirmOverwrite& confirm) {
  std::string path = withImageSuffix(chosen);
  if (path.empty()) return std::nullopt;
  std::error_code ec;
  // Anything already there (even a folder or a dangling link) needs the user's word.
  bool exists = std::filesystem::exists(std::filesystem::symlink_status(path, ec));
  if (exists && !(confirm && confirm(path))) return std::nullopt;
  return path;
}

}  // namespace voxray
