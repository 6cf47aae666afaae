// The cache of retrieved series: index, size cap with least-recently-used eviction.
#include <sys/mount.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <gmock/gmock.h>

#include "pacs_test_support.h"

namespace voxray::test {
namespace {

using CacheTest = PacsTest;

// The GE tilt study's only series, found by C-FIND.
PacsMatch tiltSeriesOf(PacsClient& client) {
  auto tilt = findByName(client, "REM*");
  EXPECT_EQ(tilt.size(), 1u);
  PacsQuery q;
  q.level = QueryLevel::Series;
  q.studyInstanceUid = tilt.empty() ? "" : tilt[0].studyInstanceUid;
  auto series = client.find(q);
  EXPECT_EQ(series.size(), 1u);
  return series.empty() ? PacsMatch{} : series[0];
}

// What FOLDER takes on disk, as du(1) counts it (allocated blocks of files, folders and
// links): the cap's measure, taken by another program than the cache.
uint64_t duBytes(const std::string& folder) {
  std::string command = "du -s -B1 '" + folder + "'";
  FILE* p = popen(command.c_str(), "r");
  unsigned long long bytes = 0;
  if (!p || std::fscanf(p, "%llu", &bytes) != 1) ADD_FAILURE() << "cannot run " << command;
  if (p) pclose(p);
  return bytes;
}

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

// The cap counts all the cache writes, as du does: a study's view under studies/ (28 links,
// a block each on this file system since their targets are long) and the index, not only
// the series' files. A cap that holds both series but not the view besides them: making the
// view evicts the other series, never the view's own.
TEST_F(CacheTest, TheCapCountsTheStudyViewsAndTheIndexAsDuDoes) {
  auto client = makePacsClient(server().dimseNode());
  PacsMatch tilt = tiltSeriesOf(*client);
  std::string root = tempFolder("cache");
  CachedSeries phantom, tiltEntry;
  {
    PacsCache unlimited(root);
    phantom = unlimited.retrieve(*client, kPhantomStudy, kPhantomSeries);
    tiltEntry = unlimited.retrieve(*client, tilt.studyInstanceUid, tilt.seriesInstanceUid);
  }
  const uint64_t both = duBytes(root);
  // The series' own count is du's for their folders (28 files of 0.5 MB each).
  EXPECT_EQ(phantom.bytes, duBytes(phantom.folder));
  EXPECT_EQ(tiltEntry.bytes, duBytes(tiltEntry.folder));
  EXPECT_GT(both, phantom.bytes + tiltEntry.bytes);  // + the index and the folders
  PacsCache(root).studyFolder(kPhantomStudy, {phantom});
  const uint64_t view = duBytes(root) - both;
  ASSERT_GE(view, 28u * 4096u) << "28 links to long paths take a 4 KiB block each on ext4";

  const uint64_t cap = both + view / 2;
  PacsCache capped(root, cap);
  std::string folder = capped.studyFolder(kPhantomStudy, {phantom});
  auto entries = capped.entries();
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].seriesUid, kPhantomSeries);
  EXPECT_FALSE(std::filesystem::exists(tiltEntry.folder));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder + "/" + kPhantomSeries),
                          std::filesystem::directory_iterator()),
            28);
  EXPECT_LE(duBytes(root), cap);
  // A retrieval into the full cache makes room the same way: the view (of a series now
  // evicted) goes with its series, and everything stays within the cap.
  capped.retrieve(*client, tilt.studyInstanceUid, tilt.seriesInstanceUid);
  EXPECT_LE(duBytes(root), cap);
  EXPECT_EQ(capped.entries().size(), 1u);
  EXPECT_FALSE(std::filesystem::exists(root + "/studies/" + kPhantomStudy));
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
