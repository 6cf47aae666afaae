// Chunks on demand for a level: opening one level of a pyramid reads the group's metadata, that
// level's array metadata and that level's chunks, each once, and no other file (counted through
// a store that records every key asked for).
#include <algorithm>
#include <mutex>

#include "voxray/io/load.h"
#include "zarr_test_support.h"

namespace voxray::test {
namespace {

class CountingStore final : public ZarrStore {
 public:
  explicit CountingStore(const std::string& folder) : folder_(zarrFolderStore(folder)) {}
  std::string where(const std::string& key) const override { return folder_->where(key); }
  bool read(const std::string& key, std::vector<uint8_t>& data, uint64_t maxBytes,
            const std::string& tooLarge) override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      keys_.push_back(key);
    }
    return folder_->read(key, data, maxBytes, tooLarge);
  }
  std::vector<std::string> sortedKeys() {
    std::sort(keys_.begin(), keys_.end());
    return keys_;
  }

 private:
  std::unique_ptr<ZarrStore> folder_;
  std::mutex mutex_;
  std::vector<std::string> keys_;
};

class OmeZarrLevel : public ::testing::TestWithParam<int> {};

TEST_P(OmeZarrLevel, ALevelReadsItsMetadataAndItsChunksOnly) {
  const int version = GetParam();
  TempDir dir;
  const std::string path = dir.file("v.ome.zarr");
  ZarrWriteOptions o;
  o.zarrVersion = version;
  o.chunk = 16;
  o.levels = 3;
  // 45 x 38 x 29, 23 x 19 x 15, 12 x 10 x 8: 3 x 3 x 2, 2 x 2 x 1 and 1 chunks.
  const ZarrWriteResult written = writeOmeZarr(zarrTestVolume(), path, o);
  ASSERT_EQ(written.chunks, 18u + 4u + 1u);
  const std::string chunkPrefix = version == 2 ? "/" : "/c/";
  for (int level : {1, 2}) {
    CountingStore store(path);
    LoadOptions load;
    load.level = level;
    const Volume v = importOmeZarr(store, load);
    EXPECT_EQ(v.dims, written.dims[size_t(level)]);
    const std::string l = std::to_string(level);
    // v2: zarr.json is asked first (absent), then .zattrs; v3: zarr.json only.
    std::vector<std::string> want = {"zarr.json"};
    if (version == 2) want.push_back(".zattrs");
    want.push_back(l + (version == 2 ? "/.zarray" : "/zarr.json"));
    const int gy = level == 1 ? 2 : 1, gx = level == 1 ? 2 : 1;  // z: one chunk at both levels
    for (int y = 0; y < gy; ++y)
      for (int x = 0; x < gx; ++x)
        want.push_back(l + chunkPrefix + "0/" + std::to_string(y) + "/" + std::to_string(x));
    std::sort(want.begin(), want.end());
    EXPECT_EQ(store.sortedKeys(), want) << "level " << level;
  }
}

// loadVolume (voxray_io, no network code) names a URL for what it is, without its credentials.
TEST(OmeZarrUrlOutsideTheFrontEnds, IsRefusedWithoutItsCredentials) {
  const std::string message =
      errorMessage([] { loadVolume("https://ann:secret@example.org/x.ome.zarr"); });
  EXPECT_EQ(message,
            "https URL: only the main input of voxray-cli and the workstation may be a URL (an "
            "OME-Zarr); give a local file or folder here");
}

INSTANTIATE_TEST_SUITE_P(ZarrVersions, OmeZarrLevel, ::testing::Values(2, 3), [](const auto& info) {
  return std::string(info.param == 2 ? "v2" : "v3");
});

}  // namespace
}  // namespace voxray::test
