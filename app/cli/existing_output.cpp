#include "existing_output.h"

#include <filesystem>

#include "voxray/io/error.h"

namespace voxray::cli {

void refuseExisting(const std::string& path, bool replace, const char* flag) {
  std::error_code ec;
  if (!path.empty() && !replace && std::filesystem::exists(path, ec))
    throw outputError(path + " exists: give " + flag + " to replace it, or another name.");
}

}  // namespace voxray::cli
