// What the cache keeps (issue 39, defect 17): only a series whose files are all of it, each
// a DICOM instance of its own; staging folders left by a crash go when a cache opens, those
// of a live retrieval stay.
#include <fcntl.h>
#include <linux/fs.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>

#include <gmock/gmock.h>

#include "pacs_test_support.h"
#include "voxray/io/dicom_import.h"

namespace voxray::test {
namespace {

namespace fs = std::filesystem;
using testing::HasSubstr;

// A node that "retrieves" by copying files: WRITE gets the staging folder, returns the files
// it reports. HAND_OVER: each file's bytes also go to RetrieveOptions::arrived and ::written,
// as WADO-RS hands them over (by default the bytes on disk; HANDED may give others).
class CopyingClient : public PacsClient {
 public:
  explicit CopyingClient(std::function<std::vector<std::string>(const std::string&)> write,
                         bool handOver = false,
                         std::function<std::string(const std::string&)> handed = {})
      : write_(std::move(write)), handOver_(handOver), handed_(std::move(handed)) {}
  void echo() override {}
  FindResult findPages(const PacsQuery&, const FindOptions&) override { return {}; }
  std::vector<std::string> retrieveSeries(const std::string&, const std::string&,
                                          const std::string& folder,
                                          const RetrieveOptions& options) override {
    std::vector<std::string> files = write_(folder);
    if (handOver_)
      for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        auto shared = std::make_shared<const std::string>(handed_ ? handed_(f) : bytes);
        if (options.arrived) options.arrived(f, shared);
        if (options.written) options.written(f, *shared);
      }
    return files;
  }
  void store(const std::vector<std::string>&, const std::atomic<bool>*) override {}

 private:
  std::function<std::vector<std::string>(const std::string&)> write_;
  bool handOver_;
  std::function<std::string(const std::string&)> handed_;
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

// IMPORTED: the files handed over also go to an import (pacs get's way), from whose reading
// of them the cache takes their identities.
std::string stagedRetrieveFailure(
    const std::function<std::vector<std::string>(const std::string&)>& write, bool handOver = false,
    bool imported = false) {
  PacsCache cache(tempFolder("cache"));
  CopyingClient client(write, handOver);
  DicomImport import;
  std::string m = failure([&] {
    cache.retrieve(client, kPhantomStudy, kPhantomSeries, {}, imported ? &import : nullptr);
  });
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
  std::string m = stagedRetrieveFailure([](const std::string& f) {
    return copyPhantom(f, {"S2010/I10", "S1000/I10"});
  });
  EXPECT_THAT(m,
              testing::AllOf(HasSubstr("Series " + std::string(kPhantomSeries)), HasSubstr("1.dcm"),
                             HasSubstr("belongs to series"), HasSubstr("nothing was kept")));
}

TEST(CacheStagingTest, MoreFilesThanReportedAreNotKept) {
  std::string m = stagedRetrieveFailure([](const std::string& f) {
    auto files = copyPhantom(f, {"S2010/I10", "S2010/I100"});
    files.pop_back();
    return files;
  });
  EXPECT_THAT(m, HasSubstr("1 images were reported but 2 files arrived"));
}

TEST(CacheStagingTest, TheSameInstanceTwiceIsNotKept) {
  std::string m = stagedRetrieveFailure([](const std::string& f) {
    return copyPhantom(f, {"S2010/I10", "S2010/I10"});
  });
  EXPECT_THAT(m, HasSubstr("came twice"));
}

TEST(CacheStagingTest, AFileThatIsNotDicomIsNotKept) {
  std::string m = stagedRetrieveFailure([](const std::string& f) {
    std::ofstream(f + "/0.dcm") << "<html>login</html>";
    return std::vector<std::string>{f + "/0.dcm"};
  });
  EXPECT_THAT(m, HasSubstr("0.dcm, which is not an image of it"));
}

// Files handed over as they arrive (WADO-RS) are checked from their bytes, with the same
// messages as files read from disk (issue 39 item 8: nothing is read back).
TEST(CacheStagingTest, HandedOverFilesGiveTheSameVerdicts) {
  for (int way = 0; way < 3; ++way) {
    const bool handOver = way > 0, imported = way == 2;
    SCOPED_TRACE(imported ? "handed over to an import" : handOver ? "handed over" : "from disk");
    EXPECT_THAT(
        stagedRetrieveFailure(
            [](const std::string& f) {
              return copyPhantom(f, {"S2010/I10", "S1000/I10"});
            },
            handOver, imported),
        testing::AllOf(HasSubstr("1.dcm, which is not an image of it (it belongs to series"),
                       HasSubstr("nothing was kept")));
    EXPECT_THAT(stagedRetrieveFailure(
                    [](const std::string& f) {
                      return copyPhantom(f, {"S2010/I10", "S2010/I10"});
                    },
                    handOver, imported),
                HasSubstr("1.dcm, which is not an image of it (its SOP Instance UID came twice)"));
    EXPECT_THAT(stagedRetrieveFailure(
                    [](const std::string& f) {
                      std::ofstream(f + "/0.dcm") << "<html>login</html>";
                      return std::vector<std::string>{f + "/0.dcm"};
                    },
                    handOver, imported),
                HasSubstr("0.dcm, which is not an image of it"));
  }
  PacsCache cache(tempFolder("cache"));
  CopyingClient client(
      [](const std::string& f) {
        return copyPhantom(f, {"S2010/I10", "S2010/I100"});
      },
      true);
  EXPECT_EQ(cache.retrieve(client, kPhantomStudy, kPhantomSeries).images, 2);
}

// The verdict on a handed-over file comes from the bytes handed over, not from reading the
// file back: bytes of another series fail a series whose files on disk are right.
TEST(CacheStagingTest, HandedOverFilesAreCheckedFromTheirBytes) {
  PacsCache cache(tempFolder("cache"));
  CopyingClient client(
      [](const std::string& f) {
        return copyPhantom(f, {"S2010/I10", "S2010/I100"});
      },
      true,
      [](const std::string&) {
        std::ifstream in(dicomPath("ct-philips-phantom/S1000/I10"), std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      });
  EXPECT_THAT(failure([&] { cache.retrieve(client, kPhantomStudy, kPhantomSeries); }),
              HasSubstr("0.dcm, which is not an image of it (it belongs to series"));
  expectNothingCached(cache);
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

// Each retrieval's folder is placed away from its siblings (ext4's FS_TOPDIR_FL on
// staging/, staged_series.h says why): where the file system keeps such flags, it is set.
TEST(CacheStagingTest, StagingAsksForNewFoldersToBeSpread) {
  PacsCache cache(tempFolder("cache"));
  const std::string staging = cache.root() + "/staging";
  const int fd = open(staging.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  ASSERT_GE(fd, 0) << staging;
  int flags = 0;
  const bool hasFlags = ioctl(fd, FS_IOC_GETFLAGS, &flags) == 0;
  close(fd);
  if (!hasFlags) GTEST_SKIP() << "this file system keeps no inode flags";
  EXPECT_TRUE(flags & FS_TOPDIR_FL) << "flags " << std::hex << flags;
}

}  // namespace
}  // namespace voxray::test
