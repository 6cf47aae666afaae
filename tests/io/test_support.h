#pragma once
// Helpers shared by the io tests: the shared data folder, scratch folders under /tmp and a
// checksum of voxels.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "voxray/io/error.h"
#include "voxray/io/raw_import.h"
#include "voxray/io/volume.h"

namespace voxray::test {

inline std::string dataPath(const std::string& relative) {
  return std::string(VOXRAY_DATA_DIR) + "/" + relative;
}

// The Stanford CThead slice folder as its layout is known: 256 x 256 int16 big-endian,
// Z = 0 (every file).
inline RawLayout ctHeadFolderLayout() {
  RawLayout l;
  l.dims = {256, 256, 0};
  l.type = SampleType::I16;
  l.order = ByteOrder::Big;
  return l;
}

// A fresh folder under the system temp folder, removed with everything in it at the end.
class TempDir {
 public:
  TempDir() {
    std::random_device seed;
    path_ = std::filesystem::temp_directory_path() /
            ("voxray-io-test-" + std::to_string(seed()) + std::to_string(seed()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline void writeBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  ASSERT_TRUE(out.good()) << path;
}

inline std::vector<uint8_t> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// 64-bit FNV-1a over the voxels as little-endian int16 bytes.
inline uint64_t checksum(const Volume& v) {
  uint64_t h = 1469598103934665603ull;
  for (int16_t s : v.voxels) {
    const auto u = uint16_t(s);
    for (uint8_t byte : {uint8_t(u & 0xff), uint8_t(u >> 8)}) {
      h ^= byte;
      h *= 1099511628211ull;
    }
  }
  return h;
}

// The message of the voxray::Error that `f` throws; fails the test if it throws none.
template <class F>
std::string errorMessage(F&& f, Error::Kind kind = Error::Kind::Input) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(int(e.kind()), int(kind)) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "expected a voxray::Error";
  return {};
}

}  // namespace voxray::test
