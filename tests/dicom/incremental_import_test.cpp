// DicomImport (files fed as they arrive, issue 12) gives importDicom's volume bit for bit and
// its errors, whatever the order the files came in and whichever of them were fed.
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <unistd.h>

#include "../io/test_support.h"
#include "folder_bytes.h"
#include "test_data.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/phantom_series.h"

namespace voxray {
namespace {

namespace fs = std::filesystem;
using test::dicomPath;
using test::filesOf;

uint64_t checksum(const Volume& v) {
  uint64_t h = 1469598103934665603ull;  // FNV-1a: equal volumes, equal sums
  for (int16_t s : v.voxels) h = (h ^ uint16_t(s)) * 1099511628211ull;
  return h;
}

// Exact equality: the same decode and the same geometry code run either way.
void expectSame(const Volume& fed, const Volume& disk) {
  EXPECT_EQ(fed.dims, disk.dims);
  EXPECT_EQ(fed.spacingMm, disk.spacingMm);
  EXPECT_EQ(fed.originMm, disk.originMm);
  EXPECT_EQ(fed.slope, disk.slope);
  EXPECT_EQ(fed.intercept, disk.intercept);
  EXPECT_EQ(fed.voxels.size(), disk.voxels.size());
  EXPECT_EQ(checksum(fed), checksum(disk));
  EXPECT_EQ(fed.warnings, disk.warnings);
}

Volume fedImport(const std::string& folder, std::vector<std::pair<std::string, std::string>> files,
                 const LoadOptions& options = {}) {
  DicomImport import(options);
  for (auto& [path, bytes] : files) import.add(path, std::move(bytes));
  return import.finish(folder);
}

TEST(DicomIncremental, FilesInAnyOrderGiveTheDiskVolumeBitForBit) {
  const std::string folder = dicomPath("ct-philips-phantom/S2010");
  const Volume disk = importDicom(folder);
  auto files = filesOf(folder);
  ASSERT_EQ(files.size(), 29u);  // 28 slices and a DICOMDIR-like DIRFILE
  // The fed slices are used (not read again from disk): the import says so.
  std::vector<std::string> said;
  LoadOptions o;
  o.progress = [&](double, const std::string& what) { said.push_back(what); };
  expectSame(fedImport(folder, files, o), disk);
  EXPECT_TRUE(test::anyContains(said, "Decoded 28 slices as they arrived"));
  std::reverse(files.begin(), files.end());  // every slice moves in the reorder
  expectSame(fedImport(folder, files), disk);
  std::shuffle(files.begin(), files.end(), std::mt19937(12));
  expectSame(fedImport(folder, files), disk);
}

// More slices than the arrival buffer reserves at first (1,024), all fed before finish(): the
// worker and the thread waiting in finish() process them at once, and the buffer grows while
// both take slots. Reversed, so that every slice moves in the reorder too.
TEST(DicomIncremental, ASeriesPastTheReservedSlicesGivesTheDiskVolume) {
  test::TempDir dir;
  PetSpherePhantom p;
  p.dims = {8, 8, 1100};
  p.spacingMm = {4.0, 4.0, 0.25};  // the sphere still crosses many slices
  writePetSpherePhantom(dir.file("pt"), p);
  const Volume disk = importDicom(dir.file("pt"));
  ASSERT_EQ(disk.dims, glm::ivec3(8, 8, 1100));
  auto files = filesOf(dir.file("pt"));
  ASSERT_EQ(files.size(), 1100u);
  std::reverse(files.begin(), files.end());
  std::vector<std::string> said;
  LoadOptions o;
  o.progress = [&](double, const std::string& what) { said.push_back(what); };
  expectSame(fedImport(dir.file("pt"), files, o), disk);
  EXPECT_TRUE(test::anyContains(said, "Decoded 1100 slices as they arrived"));
}

TEST(DicomIncremental, FinishingTwiceReadsTheSecondTimeFromDisk) {
  const std::string folder = dicomPath("ct-philips-phantom/S2010");
  DicomImport import;
  for (auto& [path, bytes] : filesOf(folder)) import.add(path, std::move(bytes));
  const Volume first = import.finish(folder);
  expectSame(import.finish(folder), first);
}

TEST(DicomIncremental, SomeFilesFedTheOthersReadFromDisk) {
  const std::string folder = dicomPath("ct-philips-phantom/S2010");
  auto files = filesOf(folder);
  files.resize(files.size() / 2);
  expectSame(fedImport(folder, files), importDicom(folder));
}

// Three series fed: the default choice and its volume are importDicom's (the fed slices of
// the other series stay unused, so the volume is assembled by copying).
TEST(DicomIncremental, AStudyOfSeveralSeriesChoosesAndLoadsAsFromDisk) {
  const std::string folder = dicomPath("ct-philips-phantom");
  expectSame(fedImport(folder, filesOf(folder)), importDicom(folder));
}

TEST(DicomIncremental, CompressedFilesGiveTheDiskVolume) {
  const std::string folder = dicomPath("transfer-syntaxes");
  LoadOptions o;
  for (const auto& info : listDicomSeries(folder).series) {
    o.series = info.selector;
    std::vector<std::string> said;
    o.progress = [&](double, const std::string& what) { said.push_back(what); };
    DicomImport import(o);
    for (auto& [path, bytes] : filesOf(folder)) import.add(path, std::move(bytes));
    Volume fed, disk;
    std::string fedError, diskError;
    try {
      fed = import.finish(folder);
    } catch (const Error& e) {
      fedError = e.what();
    }
    try {
      disk = importDicom(folder, o);
    } catch (const Error& e) {
      diskError = e.what();
    }
    SCOPED_TRACE(info.selector + " " + info.transferSyntax);
    EXPECT_EQ(fedError, diskError);
    if (!diskError.empty()) continue;
    expectSame(fed, disk);
    // Decoded from the fed bytes (their pixel data read where it lies), not again from disk.
    EXPECT_TRUE(test::anyContains(said, "as they arrived"));  // either way of using them
  }
}

// A file cut short on disk, fed with the same bytes: the worker cannot decode it, the import
// reads it again and says what importDicom says.
TEST(DicomIncremental, ATruncatedFileGivesImportDicomsError) {
  const std::string src = dicomPath("ct-philips-phantom/S2010");
  const fs::path folder =
      fs::temp_directory_path() / ("voxray-incremental-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  auto files = filesOf(src);
  for (auto& [path, bytes] : files) {
    path = (folder / fs::path(path).filename()).string();
    if (fs::path(path).filename() == "I100") bytes.resize(bytes.size() - 1000);
    std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  }
  const std::string diskError = test::importError(folder.string());
  ASSERT_NE(diskError.find("I100"), std::string::npos) << diskError;
  try {
    fedImport(folder.string(), files);
    ADD_FAILURE() << "the truncated file was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Input);
    EXPECT_EQ(std::string(e.what()), diskError);
  }
  fs::remove_all(folder);
}

// Bytes that do not parse as DICOM, fed (libFuzzer, session 28: the headers were still
// looked at after the parser had let go of the bytes, a use after free under ASan): the
// import says what importDicom says of the file.
TEST(DicomIncremental, BytesThatDoNotParseGiveImportDicomsError) {
  const std::string path =
      std::string(VOXRAY_FUZZ_REGRESSIONS) + "/dicom-fed-not-dicom-use-after-free.dcm";
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  ASSERT_EQ(bytes.str().size(), 235u);
  DicomImport import;
  import.add(path, bytes.str());
  std::string fedError;
  try {
    import.finish(path);
  } catch (const Error& e) {
    fedError = e.what();
  }
  const std::string diskError = test::importError(path);
  EXPECT_NE(diskError.find("dicom-fed-not-dicom-use-after-free.dcm: no DICOM image found"),
            std::string::npos)
      << diskError;
  EXPECT_EQ(fedError, diskError);
}

TEST(DicomIncremental, CancelBeforeFinishThrowsCancelled) {
  const std::string folder = dicomPath("ct-philips-phantom/S2010");
  std::atomic<bool> cancel{true};
  LoadOptions o;
  o.cancel = &cancel;
  try {
    fedImport(folder, filesOf(folder), o);
    ADD_FAILURE() << "a cancelled import returned";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::Cancelled) << e.what();
  }
}

}  // namespace
}  // namespace voxray
