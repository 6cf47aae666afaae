#pragma once
// The recent-files list: most recent first, no duplicates, a fixed length.
#include <string>
#include <vector>

#include "no_qt.h"

namespace voxray {

constexpr size_t kMaxRecentFiles = 8;

// Returns LIST with ENTRY moved (or added) to the front, trimmed to kMaxRecentFiles.
std::vector<std::string> pushRecent(std::vector<std::string> list, const std::string& entry);

}  // namespace voxray
