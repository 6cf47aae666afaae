#pragma once
// Shared by the study database tests: a fresh folder per test under the build tree, paths
// of the shared real scans.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace voxray::test {

// The shared data's Philips study and tilted series (../shared/data/dicom), by UID.
inline const std::string kPhilipsStudy =
    "1.3.46.670589.33.1.27492712521914879309.27169771283235650014";
inline const std::string kTiltSeries =
    "1.2.826.0.1.3680043.9.4245.3115138630835728997848661150714813892";

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
