#pragma once
// Paths into ../shared/data/dicom and small helpers shared by the DICOM tests.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "voxray/io/dicom_import.h"
#include "voxray/io/error.h"

namespace voxray::test {

inline std::string dicomPath(const std::string& rel) {
  return std::string(VOXRAY_DATA_DIR) + "/dicom/" + rel;
}

inline bool anyContains(const std::vector<std::string>& lines, const std::string& part) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

// The message of the Error that importDicom throws; fails the test when none is thrown.
inline std::string importError(const std::string& path, const std::string& series = {}) {
  LoadOptions o;
  o.series = series;
  try {
    importDicom(path, o);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    return e.what();
  }
  ADD_FAILURE() << "expected an Error for " << path;
  return {};
}

inline double physicalMin(const Volume& v) {
  return v.toPhysical(*std::min_element(v.voxels.begin(), v.voxels.end()));
}
inline double physicalMax(const Volume& v) {
  return v.toPhysical(*std::max_element(v.voxels.begin(), v.voxels.end()));
}

}  // namespace voxray::test
