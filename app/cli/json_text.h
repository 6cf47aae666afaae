#pragma once
// JSON as the CLI prints it. Text from files (DICOM strings, paths) is UTF-8 by the time it
// gets here; a byte that still is not (a path on a Latin-1 file system) prints as U+FFFD
// rather than throwing.
#include <string>

#include <nlohmann/json.hpp>

namespace voxray::cli {

inline std::string jsonText(const nlohmann::json& j) {
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace voxray::cli
