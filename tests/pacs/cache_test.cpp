// The cache of retrieved series: index, size cap with least-recently-used eviction.
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

TEST(CacheFolderTest, TheEnvironmentChoosesTheFolder) {
  setenv("VOXRAY_CACHE_DIR", "/tmp/voxray-cache-test", 1);
  EXPECT_EQ(defaultPacsCacheFolder(), "/tmp/voxray-cache-test");
  unsetenv("VOXRAY_CACHE_DIR");
  setenv("XDG_CACHE_HOME", "/tmp/xdg", 1);
  EXPECT_EQ(defaultPacsCacheFolder(), "/tmp/xdg/voxray");
}

}  // namespace
}  // namespace voxray::test
