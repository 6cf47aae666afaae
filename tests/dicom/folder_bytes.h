#pragma once
// Every file under a folder with its bytes, as a PACS retrieval hands files to a DicomImport
// (the fed-import tests and voxray_dicom_load_once --fed). No gtest: the bench uses it too.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace voxray::test {

// Path and bytes of every regular file under FOLDER, sorted by path.
inline std::vector<std::pair<std::string, std::string>> filesOf(const std::string& folder) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(folder)) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    out.emplace_back(e.path().string(), bytes.str());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace voxray::test
