#pragma once
// The importers read files: each fuzzing process writes its input into a folder of its
// own in memory-backed /dev/shm (never into the repository or the user's folders), removed
// when the process ends. A folder of its own matters: a DICOMDIR whose entries are missing
// makes the importer scan the folder beside it, and a shared /dev/shm full of other
// processes' inputs made each such input cost hundreds of milliseconds (issue 19).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

namespace voxray::fuzz {

inline std::string scratchPath(const std::string& name) {
  struct Folder {
    std::filesystem::path path =
        std::filesystem::path("/dev/shm") / ("voxray-fuzz-" + std::to_string(getpid()));
    Folder() { std::filesystem::create_directories(path); }
    ~Folder() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Folder folder;
  return (folder.path / name).string();
}

inline bool writeScratch(const std::string& path, const uint8_t* data, size_t size) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return false;
  const bool ok = std::fwrite(data, 1, size, f) == size;
  return std::fclose(f) == 0 && ok;
}

}  // namespace voxray::fuzz
