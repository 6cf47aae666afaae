// The series picker's background work on real DICOM folders, and the thumbnail itself.
#include <gtest/gtest.h>

#include <condition_variable>
#include <mutex>
#include <thread>

#include "series_scan.h"
#include "thumbnail.h"
#include "voxray/io/phantom.h"
#include "voxray/io/volume.h"

using namespace voxray;

TEST(Thumbnail, MiddleSliceFitsTheSquareWithItsAspect) {
  Volume v = makeHeadPhantom(32);
  v.spacingMm = {1.0, 2.0, 1.0};  // twice as tall as wide: black bands left and right
  Image t = middleSliceThumbnail(v, {400.0, 40.0}, 64);
  ASSERT_EQ(t.width, 64);
  ASSERT_EQ(t.height, 64);
  EXPECT_EQ(t.pixel(2, 32)[0], 0);  // left band
  EXPECT_EQ(t.pixel(61, 32)[0], 0);
  int lit = 0;
  for (int x = 16; x < 48; ++x) lit += t.pixel(x, 32)[0] > 0;
  EXPECT_GT(lit, 10) << "the head's soft tissue shows in the soft-tissue window";
  EXPECT_EQ(t.pixel(0, 0)[3], 255);
}

TEST(Thumbnail, OnlyCtVolumesGetTheFixedWindow) {
  Volume v = makeHeadPhantom(32);
  WindowLevel wl = defaultThumbnailWindow(v, "MR", true);
  EXPECT_GT(wl.width, 400.0);  // the phantom spans air to bone
  WindowLevel scout = defaultThumbnailWindow(v, "CT", false);
  EXPECT_DOUBLE_EQ(scout.width, wl.width);
  WindowLevel ct = defaultThumbnailWindow(v, "CT", true);
  EXPECT_DOUBLE_EQ(ct.width, 400.0);
  EXPECT_DOUBLE_EQ(ct.level, 40.0);
}

#ifdef VOXRAY_HAS_DICOM

namespace {

// Collects a scan's events; waits for the end.
struct Recorder {
  std::mutex m;
  std::condition_variable cv;
  DicomListing listing;
  std::vector<std::pair<int, Image>> thumbs;
  std::string error;
  bool done = false;
  std::thread::id eventThread;

  SeriesScanEvents events() {
    SeriesScanEvents e;
    e.listed = [this](const DicomListing& l) {
      std::lock_guard lock(m);
      listing = l;
      eventThread = std::this_thread::get_id();
    };
    e.thumbnail = [this](int i, const Image& t) {
      std::lock_guard lock(m);
      thumbs.emplace_back(i, t);
    };
    e.failed = [this](const std::string& message) { finish(message); };
    e.finished = [this] { finish({}); };
    return e;
  }
  void finish(const std::string& message) {
    std::lock_guard lock(m);
    error = message;
    done = true;
    cv.notify_all();
  }
  bool wait() {
    std::unique_lock lock(m);
    return cv.wait_for(lock, std::chrono::seconds(120), [this] { return done; });
  }
};

const std::string kPhilips = std::string(VOXRAY_DATA_DIR) + "/dicom/ct-philips-phantom";

}  // namespace

TEST(SeriesScan, ListsOffTheCallingThreadThenMakesThumbnails) {
  Recorder r;
  {
    SeriesScan scan(kPhilips, r.events());
    ASSERT_TRUE(r.wait());
  }
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_NE(r.eventThread, std::this_thread::get_id());
  ASSERT_GE(r.listing.series.size(), 2u) << "the volume, the scout and the summary pages";
  ASSERT_EQ(r.thumbs.size(), r.listing.series.size());
  const SeriesInfo& first = r.listing.series.front();
  EXPECT_TRUE(first.isVolume);
  EXPECT_EQ(r.thumbs[0].first, 0);
  ASSERT_EQ(r.thumbs[0].second.width, kThumbnailSize);
  int lit = 0;
  for (uint8_t c : r.thumbs[0].second.rgba) lit += c > 0 && c < 255;
  EXPECT_GT(lit, 100) << "the phantom's middle slice is not blank";
}

TEST(SeriesScan, CandidatesOverTheBudgetGetNoThumbnail) {
  Recorder r;
  {
    SeriesScan scan(kPhilips, r.events(), 0);
    ASSERT_TRUE(r.wait());
  }
  ASSERT_FALSE(r.thumbs.empty());
  for (const auto& [i, t] : r.thumbs) EXPECT_EQ(t.width, 0) << i;
}

TEST(SeriesScan, MissingFolderReportsTheImportersMessage) {
  Recorder r;
  {
    SeriesScan scan("/nonexistent/voxray-dicom", r.events());
    ASSERT_TRUE(r.wait());
  }
  EXPECT_NE(r.error.find("/nonexistent/voxray-dicom"), std::string::npos) << r.error;
}

TEST(SeriesScan, DestroyingItEarlyStopsWithoutEvents) {
  Recorder r;
  { SeriesScan scan(kPhilips, r.events()); }  // closed at once: must not hang or crash
  std::lock_guard lock(r.m);
  EXPECT_FALSE(r.done);
}

#endif
