// What the cache keeps (issue 39, defect 17): only a series whose files are all of it, each
// a DICOM instance of its own; staging folders left by a crash go when a cache opens, those
// of a live retrieval stay.
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>

#include <gmock/gmock.h>

#include "pacs_test_support.h"

namespace voxray::test {
namespace {

namespace fs = std::filesystem;
using testing::HasSubstr;

// A node that "retrieves" by copying files: WRITE gets the staging folder, returns the files
// it reports.
class CopyingClient : public PacsClient {
 public:
  explicit CopyingClient(std::function<std::vector<std::string>(const std::string&)> write)
      : write_(std::move(write)) {}
  void echo() override {}
  FindResult findPages(const PacsQuery&, const FindOptions&) override { return {}; }
  std::vector<std::string> retrieveSeries(const std::string&, const std::string&,
                                          const std::string& folder,
                                          const RetrieveOptions&) override {
    return write_(folder);
  }
  void store(const std::vector<std::string>&, const std::atomic<bool>*) override {}

 private:
  std::function<std::vector<std::string>(const std::string&)> write_;
};

// Copies the phantom files NAMES ("S2010/I10") into FOLDER; returns the copies.
std::vector<std::string> copyPhantom(const std::string& folder,
                                     const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const auto& n : names) {
    out.push_back(folder + "/" + std::to_string(out.size()) + ".dcm");
    fs::copy_file(dicomPath("ct-philips-phantom/" + n), out.back());
  }
  return out;
}

std::string retrieveFailure(
    const std::function<std::vector<std::string>(const std::string&)>& write) {
  PacsCache cache(tempFolder("cache"));
  CopyingClient client(write);
  std::string m = failure([&] { cache.retrieve(client, kPhantomStudy, kPhantomSeries); });
  expectNothingCached(cache);
  return m;
}

TEST(CacheStagingTest, ImagesOfTheSeriesAreKept) {
  PacsCache cache(tempFolder("cache"));
  CopyingClient client([](const std::string& f) {
    return copyPhantom(f, {"S2010/I10", "S2010/I100"});
  });
  CachedSeries s = cache.retrieve(client, kPhantomStudy, kPhantomSeries);
  EXPECT_EQ(s.images, 2);
  EXPECT_EQ(cache.entries().size(), 1u);
}

TEST(CacheStagingTest, AnImageOfAnotherSeriesIsNotKept) {
  std::string m = retrieveFailure([](const std::string& f) {
    return copyPhantom(f, {"S2010/I10", "S1000/I10"});
  });
  EXPECT_THAT(m,
              testing::AllOf(HasSubstr("Series " + std::string(kPhantomSeries)), HasSubstr("1.dcm"),
                             HasSubstr("belongs to series"), HasSubstr("nothing was kept")));
}

TEST(CacheStagingTest, MoreFilesThanReportedAreNotKept) {
  std::string m = retrieveFailure([](const std::string& f) {
    auto files = copyPhantom(f, {"S2010/I10", "S2010/I100"});
    files.pop_back();
    return files;
  });
  EXPECT_THAT(m, HasSubstr("1 images were reported but 2 files arrived"));
}

TEST(CacheStagingTest, TheSameInstanceTwiceIsNotKept) {
  std::string m = retrieveFailure([](const std::string& f) {
    return copyPhantom(f, {"S2010/I10", "S2010/I10"});
  });
  EXPECT_THAT(m, HasSubstr("came twice"));
}

TEST(CacheStagingTest, AFileThatIsNotDicomIsNotKept) {
  std::string m = retrieveFailure([](const std::string& f) {
    std::ofstream(f + "/0.dcm") << "<html>login</html>";
    return std::vector<std::string>{f + "/0.dcm"};
  });
  EXPECT_THAT(m, HasSubstr("0.dcm, which is not an image of it"));
}

// Staging folders: an old one nobody holds goes; one a live retrieval holds (locked) and a
// young one stay.
TEST(CacheStagingTest, OpeningTheCacheRemovesOnlyStaleStagingFolders) {
  std::string root = tempFolder("cache");
  const std::string staging = root + "/staging/";
  auto make = [&](const std::string& name, std::chrono::minutes age) {
    fs::create_directories(staging + name);
    std::ofstream(staging + name + "/I1.dcm") << "partial";
    fs::last_write_time(staging + name, fs::file_time_type::clock::now() - age);
  };
  make("1.2.3-crashd", std::chrono::minutes(120));
  make("1.2.4-living", std::chrono::minutes(120));
  make("1.2.5-youngg", std::chrono::minutes(0));
  const int held = open((staging + "1.2.4-living").c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(held, 0);
  ASSERT_EQ(flock(held, LOCK_EX | LOCK_NB), 0);
  PacsCache cache(root);
  EXPECT_FALSE(fs::exists(staging + "1.2.3-crashd"));
  EXPECT_TRUE(fs::exists(staging + "1.2.4-living/I1.dcm"));
  EXPECT_TRUE(fs::exists(staging + "1.2.5-youngg/I1.dcm"));
  close(held);
}

}  // namespace
}  // namespace voxray::test
