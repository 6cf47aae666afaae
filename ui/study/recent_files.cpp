#include "recent_files.h"

#include <algorithm>

namespace voxray {

std::vector<std::string> pushRecent(std::vector<std::string> list, const std::string& entry) {
  std::erase(list, entry);
  list.insert(list.begin(), entry);
  if (list.size() > kMaxRecentFiles) list.resize(kMaxRecentFiles);
  return list;
}

}  // namespace voxray
