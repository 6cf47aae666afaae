// A search that matches 10,000 studies (issue 12): a real Orthanc loaded with 10,000 tiny
// studies written here with DCMTK. C-FIND and QIDO-RS return every one, in pages as they
// arrive, or the limit with "more"; the study browser's model fills page by page while its
// owner's thread stays free.
#include <chrono>
#include <condition_variable>
#include <deque>
#include <iostream>
#include <mutex>
#include <set>
#include <thread>
#include <utility>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <gmock/gmock.h>

#include "pacs_browser.h"
#include "pacs_test_support.h"

namespace voxray::test {
namespace {

constexpr int kStudies = 10000;

// Study I: patient MANY^I, one series of one instance without pixels (what C-FIND and
// QIDO-RS read is the header), dated over 2020.
void writeTinyStudy(const std::string& folder, int i) {
  const std::string root = "1.2.826.0.1.3680043.10.1082.12." + std::to_string(i);
  DcmFileFormat file;
  DcmDataset& d = *file.getDataset();
  d.putAndInsertString(DCM_SOPClassUID, UID_SecondaryCaptureImageStorage);
  d.putAndInsertString(DCM_SOPInstanceUID, (root + ".3").c_str());
  d.putAndInsertString(DCM_StudyInstanceUID, (root + ".1").c_str());
  d.putAndInsertString(DCM_SeriesInstanceUID, (root + ".2").c_str());
  d.putAndInsertString(DCM_PatientName, ("MANY^" + std::to_string(i)).c_str());
  d.putAndInsertString(DCM_PatientID, ("MANY" + std::to_string(i)).c_str());
  char date[9];
  std::snprintf(date, sizeof date, "2020%02d%02d", 1 + i % 12, 1 + i % 28);
  d.putAndInsertString(DCM_StudyDate, date);
  d.putAndInsertString(DCM_Modality, "OT");
  d.putAndInsertString(DCM_StudyDescription, "many studies");
  std::string path = folder + "/" + std::to_string(i) + ".dcm";
  if (file.saveFile(path.c_str(), EXS_LittleEndianExplicit).bad())
    throw std::runtime_error("cannot write " + path);
}

class ManyStudiesTest : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    try {
      auto t0 = std::chrono::steady_clock::now();
      auto since = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      };
      std::string files = tempFolder("many-studies");
      for (int i = 0; i < kStudies; ++i) writeTinyStudy(files, i);
      double written = since();
      server_ = std::make_unique<OrthancServer>();
      server_->upload(files);
      std::filesystem::remove_all(files);
      std::cout << kStudies << " studies written in " << written << " s, Orthanc started and "
                << "loaded in " << since() - written << " s\n";
    } catch (const std::exception& e) {
      startError_ = e.what();
    }
  }
  static void TearDownTestSuite() {
    // SIGKILL: its storage is thrown away, and a SIGTERM'd Orthanc holding 10,000 fresh
    // studies took 65 s to stop.
    if (server_) server_->stop(9);
    server_.reset();
  }
  void SetUp() override { ASSERT_TRUE(server_) << "Orthanc did not start: " << startError_; }

  static inline std::unique_ptr<OrthancServer> server_;
  static inline std::string startError_;
};

// Every study once, in pages of at most PAGE_SIZE that add up to the result.
void expectAllStudiesInPages(const PacsNode& node) {
  FindOptions options;
  options.pageSize = 2000;  // QIDO-RS: 5 requests (Orthanc scans every study for each)
  std::vector<size_t> pages;
  std::set<std::string> seen;
  options.page = [&](const std::vector<PacsMatch>& page) {
    pages.push_back(page.size());
    for (const auto& m : page) seen.insert(m.studyInstanceUid);
  };
  FindResult all = makePacsClient(node)->findPages({}, options);  // the server holds only these
  EXPECT_EQ(all.matches.size(), size_t(kStudies));
  EXPECT_FALSE(all.more);
  EXPECT_EQ(seen.size(), size_t(kStudies));
  EXPECT_EQ(pages.size(), size_t(kStudies / 2000));
  for (size_t n : pages) EXPECT_EQ(n, 2000u);
}

void expectLimitSaysMore(const PacsNode& node) {
  PacsQuery q;
  q.limit = 2500;
  FindResult some = makePacsClient(node)->findPages(q, {});
  EXPECT_EQ(some.matches.size(), 2500u);
  EXPECT_TRUE(some.more);
  q.limit = kStudies;  // exactly all: nothing more
  FindOptions big;
  big.pageSize = 5000;
  FindResult all = makePacsClient(node)->findPages(q, big);
  EXPECT_EQ(all.matches.size(), size_t(kStudies));
  EXPECT_FALSE(all.more);
}

TEST_F(ManyStudiesTest, CFindReturnsAll10000InPages) {
  expectAllStudiesInPages(server_->dimseNode());
}

TEST_F(ManyStudiesTest, QidoRsReturnsAll10000InPages) {
  expectAllStudiesInPages(server_->webNode());
}

TEST_F(ManyStudiesTest, CFindLimitSaysThereIsMore) { expectLimitSaysMore(server_->dimseNode()); }

TEST_F(ManyStudiesTest, QidoRsLimitSaysThereIsMore) { expectLimitSaysMore(server_->webNode()); }

// The browser's events go to a queue that this (the "GUI") thread drains, as the
// workstation's postTo does. The search's thread is held at its first page until this
// thread has shown it: the list fills while the search still runs (not a timed test), and
// this thread never waits on the search.
TEST_F(ManyStudiesTest, TheBrowserModelFillsPageByPage) {
  std::mutex mutex;
  std::condition_variable shown;
  std::deque<BackgroundTask::Event> queue;
  bool firstPosted = false, firstShown = false;
  auto post = [&](BackgroundTask::Event e) {
    std::unique_lock<std::mutex> lock(mutex);
    queue.push_back(std::move(e));
    if (std::exchange(firstPosted, true)) return;
    shown.wait(lock, [&] { return firstShown; });
  };
  std::vector<size_t> pages;
  size_t listed = 0, found = 0;
  bool done = false, more = true, searchingAtFirstPage = false;
  PacsBrowser* browser = nullptr;
  PacsBrowserEvents events;
  events.studies = [&](const std::vector<PacsMatch>& page) {
    if (pages.empty()) searchingAtFirstPage = browser->busy() && !done;
    pages.push_back(page.size());
    listed += page.size();
  };
  events.found = [&](size_t count, bool m) {
    found = count;
    more = m;
    done = true;
  };
  events.failed = [&](const std::string& message) {
    ADD_FAILURE() << message;
    done = true;
  };
  PacsBrowser model(events, tempFolder("cache"), post);
  browser = &model;
  PacsQuery q;
  model.search("dicom://" + server_->dimseNode().label(), q);
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!done && std::chrono::steady_clock::now() < deadline) {
    std::deque<BackgroundTask::Event> now;
    {
      std::lock_guard<std::mutex> lock(mutex);
      now.swap(queue);
    }
    for (auto& e : now) e();
    if (!pages.empty()) {
      std::lock_guard<std::mutex> lock(mutex);
      firstShown = true;
      shown.notify_all();
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(done) << "the search did not finish in 120 s";
  EXPECT_TRUE(searchingAtFirstPage);
  EXPECT_EQ(found, size_t(kStudies));
  EXPECT_EQ(listed, size_t(kStudies));
  EXPECT_FALSE(more);
  EXPECT_EQ(pages.size(), size_t(kStudies) / PacsBrowser::kPageSize);
}

}  // namespace
}  // namespace voxray::test
