// The cache of retrieved series: index, size cap with least-recently-used eviction.
#include <sys/mount.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <gmock/gmock.h>

#include "pacs_test_support.h"

namespace voxray::test {
namespace {

using CacheTest = PacsTest;

TEST_F(CacheTest, OverTheCapTheLeastRecentlyUsedSeriesGoes) {
  auto client = makePacsClient(server().dimseNode());
  auto tilt = findByName(*client, "REM*");
  ASSERT_EQ(tilt.size(), 1u);
  PacsQuery q;
  q.level = QueryLevel::Series;
  q.studyInstanceUid = tilt[0].studyInstanceUid;
  auto tiltSeries = client->find(q);
  ASSERT_EQ(tiltSeries.size(), 1u);

  std::string root = tempFolder("cache");
  CachedSeries phantom = PacsCache(root).retrieve(*client, kPhantomStudy, kPhantomSeries);
  // A cap that holds the phantom series but not both.
  PacsCache cache(root, phantom.bytes + 1);
  EXPECT_TRUE(cache.find(kPhantomSeries));
  CachedSeries second =
      cache.retrieve(*client, tilt[0].studyInstanceUid, tiltSeries[0].seriesInstanceUid);
  EXPECT_EQ(second.images, 28);
  auto entries = cache.entries();
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].seriesUid, tiltSeries[0].seriesInstanceUid);
  EXPECT_FALSE(std::filesystem::exists(phantom.folder));
  // A second retrieval of a cached series is served from the cache (same folder).
  EXPECT_EQ(
      cache.retrieve(*client, tilt[0].studyInstanceUid, tiltSeries[0].seriesInstanceUid).folder,
      second.folder);
}

// A real file system that fills: an 8 MiB tmpfs mounted for the test. The 28-image phantom
// series (15 MB) cannot fit; its 1-image series (0.3 MB) can. Mounting needs root (CI runs
// as root); without it the test fails saying so rather than faking ENOSPC.
struct SmallDisk {
  std::string path = tempFolder("full-disk");
  std::string error;
  SmallDisk() {
    if (mount("tmpfs", path.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "size=8m") != 0)
      error = "cannot mount an 8 MiB tmpfs at " + path + " (" + std::strerror(errno) +
              "): this test needs root (CAP_SYS_ADMIN) to fill a real file system";
  }
  ~SmallDisk() {
    if (error.empty()) umount2(path.c_str(), MNT_DETACH);
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

// The phantom study's 1-image series (S1000), found by C-FIND.
std::string oneImageSeries(PacsClient& client) {
  PacsQuery q;
  q.level = QueryLevel::Series;
  q.studyInstanceUid = kPhantomStudy;
  for (const auto& s : client.find(q))
    if (s.numberOfInstances == 1) return s.seriesInstanceUid;
  ADD_FAILURE() << "the phantom study has no 1-image series";
  return {};
}

void expectFullDiskSaysSoAndGoesOn(const PacsNode& node) {
  SmallDisk disk;
  ASSERT_TRUE(disk.error.empty()) << disk.error;
  PacsCache cache(disk.path + "/cache");
  auto client = makePacsClient(node);
  std::string message = failure([&] { cache.retrieve(*client, kPhantomStudy, kPhantomSeries); });
  EXPECT_THAT(message, testing::HasSubstr("the cache at " + cache.root() +
                                          " is full: free space or set VOXRAY_CACHE_DIR"));
  expectNothingCached(cache);
  // The program goes on: the same cache (space freed by the staged files' removal) takes a
  // series that fits.
  CachedSeries small = cache.retrieve(*client, kPhantomStudy, oneImageSeries(*client));
  EXPECT_EQ(small.images, 1);
  ASSERT_EQ(cache.entries().size(), 1u);
  EXPECT_EQ(cache.entries()[0].seriesUid, small.seriesUid);
  EXPECT_FALSE(cache.find(kPhantomSeries));
}

TEST_F(CacheTest, AFullCacheDiskStopsCGetWithAClearMessageAndKeepsNothing) {
  expectFullDiskSaysSoAndGoesOn(server().dimseNode());
}

TEST_F(CacheTest, AFullCacheDiskStopsWadoRsWithAClearMessageAndKeepsNothing) {
  expectFullDiskSaysSoAndGoesOn(server().webNode());
}

TEST(CacheFolderTest, TheEnvironmentChoosesTheFolder) {
  setenv("VOXRAY_CACHE_DIR", "/tmp/voxray-cache-test", 1);
  EXPECT_EQ(defaultPacsCacheFolder(), "/tmp/voxray-cache-test");
  unsetenv("VOXRAY_CACHE_DIR");
  setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  EXPECT_EQ(defaultPacsCacheFolder(), "/tmp/xdg/voxray");
}

}  // namespace
}  // namespace voxray::test
