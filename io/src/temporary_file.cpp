#include "voxray/io/temporary_file.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>

namespace voxray {

std::filesystem::path temporaryBeside(const std::filesystem::path& target) {
  return temporaryBeside(target, target.extension().string());
}

std::filesystem::path temporaryBeside(const std::filesystem::path& target,
                                      const std::string& extension) {
  static std::atomic<unsigned> counter{0};
  std::string stem = target.filename().string();
  stem.resize(stem.size() - std::min(stem.size(), extension.size()));
  std::string name = ".";  // appended, not "." + ...: GCC 12 warns falsely on that
  name += stem + ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + extension;
  return target.parent_path() / name;
}

}  // namespace voxray
