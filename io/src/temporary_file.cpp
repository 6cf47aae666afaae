#include "temporary_file.h"

#include <unistd.h>

#include <atomic>
#include <string>

namespace voxray {

std::filesystem::path temporaryBeside(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  std::string name = ".";  // appended, not "." + ...: GCC 12 warns falsely on that
  name += target.stem().string() + ".tmp" + std::to_string(::getpid()) + "-" +
          std::to_string(counter++) + target.extension().string();
  return target.parent_path() / name;
}

}  // namespace voxray
