#pragma once
// Shared by the study database tests: a fresh folder per test under the build tree, paths
// of the shared real scans.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace voxray::test {

inline std::string dicomPath(const std::string& rel) {
  return std::string(VOXRAY_DATA_DIR) + "/dicom/" + rel;
}

// An empty folder named after the running test (and SUFFIX), made afresh.
inline std::string tempFolder(const std::string& suffix) {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir =
      std::filesystem::path(VOXRAY_TEST_TMP) /
      (std::string(info->test_suite_name()) + "." + info->name() + "." + suffix);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace voxray::test
