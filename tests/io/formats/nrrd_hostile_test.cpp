// Hostile NRRD headers (issue 39, found by fuzzing): detached data-file patterns that overflow
// Teem's name buffer or count for ever, data files outside the header's folder or of the wrong
// size, and headers long enough to make Teem's parser take minutes. Each is refused before Teem
// reads it, quickly, with a message saying what is wrong; the files are written into a
// temporary folder the test makes.
#include <sys/stat.h>

#include <chrono>
#include <filesystem>

#include "format_test_support.h"
#include "voxray/io/load.h"

namespace voxray {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using testing::HasSubstr;

// A 4 x 3 x 2 short volume whose data file field is DATA_FILE (and any lines after it).
std::string hostileNrrdHeader(const std::string& dataFile) {
  return "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\n"
         "data file: " +
         dataFile + "\n";
}

// N little-endian int16 values FIRST, FIRST + 1, ...
std::vector<uint8_t> shorts(int n, int first) {
  std::vector<uint8_t> b;
  for (int i = 0; i < n; ++i) {
    b.push_back(uint8_t((first + i) & 0xff));
    b.push_back(uint8_t(uint16_t(first + i) >> 8));
  }
  return b;
}

using test::loadError;

// The error for a .nhdr holding HEADER in a fresh folder "study" inside DIR.
std::string nhdrError(const TempDir& dir, const std::string& text) {
  fs::create_directories(dir.path() / "study");
  const std::string path = (dir.path() / "study" / "v.nhdr").string();
  test::writeHeaderFile(path, text);
  return loadError(path);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(FormatsNrrdHostile, SlicePatternsThatOpenAreReadInOrder) {
  TempDir dir;
  test::writeBytes(dir.file("slice007.raw"), shorts(12, 0));
  test::writeBytes(dir.file("slice009.raw"), shorts(12, 100));
  test::writeHeaderFile(dir.file("v.nhdr"), hostileNrrdHeader("slice%03d.raw 7 9 2"));
  const Volume v = loadVolume(dir.file("v.nhdr"));
  ASSERT_EQ(v.dims, glm::ivec3(4, 3, 2));
  EXPECT_EQ(v.toPhysical(v.at(3, 2, 0)), 11.0);
  EXPECT_EQ(v.toPhysical(v.at(1, 0, 1)), 101.0);
}

// Teem printed "slice%0999999d.raw" into a buffer 10 characters longer than the pattern
// (SIGSEGV or glibc's "buffer overflow detected").
TEST(FormatsNrrdHostile, PatternsTeemCannotPrintAreRefused) {
  for (const char* pattern : {"slice%0999999d.raw 0 1 1", "slice%016d.raw 0 1 1",
                              "slice%03d%s.raw 0 1 1", "slice%03d.raw 0 1 1 9 9"}) {
    SCOPED_TRACE(pattern);
    TempDir dir;
    EXPECT_THAT(nhdrError(dir, hostileNrrdHeader(pattern)),
                HasSubstr("its data file pattern '" + std::string(pattern) +
                          "' is not one Voxray reads (NAME%03d.raw FIRST LAST STEP"));
  }
}

// Teem counted "0 2147483647 1" with an int that overflows: a loop without end (> 60 s).
TEST(FormatsNrrdHostile, PatternRangesBeyondTheSizesAreRefusedQuickly) {
  TempDir dir;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("slice%03d.raw 0 2147483647 1")),
              HasSubstr("numbers of at most 9 digits"));
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("slice%03d.raw 0 999999 1")),
              HasSubstr("the header names 1000000 data files; at most 24 are read"));
  EXPECT_LT(secondsSince(start), 5.0);
}

// "data file:" read /etc/passwd, /proc/self/environ or a link to a file outside as voxels.
TEST(FormatsNrrdHostile, DataFilesOutsideTheHeadersFolderAreRefused) {
  TempDir dir;
  test::writeBytes(dir.file("outside.raw"), shorts(24, 0));
  fs::create_directories(dir.path() / "elsewhere");
  test::writeBytes((dir.path() / "elsewhere" / "x.raw").string(), shorts(24, 0));
  fs::create_directories(dir.path() / "study");
  fs::create_symlink(dir.file("outside.raw"), dir.path() / "study" / "link.raw");
  fs::create_directory_symlink(dir.path() / "elsewhere", dir.path() / "study" / "sub");
  for (const std::string& name : {std::string("/etc/passwd"), std::string("/proc/self/environ"),
                                  std::string("../outside.raw"), dir.file("outside.raw"),
                                  std::string("link.raw"), std::string("sub/x.raw")}) {
    SCOPED_TRACE(name);
    EXPECT_THAT(nhdrError(dir, hostileNrrdHeader(name)),
                HasSubstr("its data file '" + name + "' lies outside the header's folder"));
  }
  // The list and pattern forms are held to the same rule.
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("LIST\n../outside.raw\n../outside.raw")),
              HasSubstr("its data file '../outside.raw' lies outside the header's folder"));
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("../outside%d.raw 1 2 1")),
              HasSubstr("its data file '../outside1.raw' is missing"));
  // A lone carriage return may end a line for Teem and not for the check: refused as not text.
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("x.raw\r../outside.raw")),
              HasSubstr("header line 7 holds the byte 0x0d, which is not text"));
  test::writeBytes(dir.file("outside1.raw"), shorts(12, 0));
  test::writeBytes(dir.file("outside2.raw"), shorts(12, 0));
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("../outside%d.raw 1 2 1")),
              HasSubstr("its data file '../outside1.raw' lies outside the header's folder"));
}

TEST(FormatsNrrdHostile, DataFilesThatAreNoRegularFilesAreRefused) {
  TempDir dir;
  fs::create_directories(dir.path() / "study" / "folder");
  ASSERT_EQ(mkfifo((dir.path() / "study" / "pipe.raw").c_str(), 0600), 0);
  // Teem opened a FIFO (blocking for ever) and "-" (standard input).
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("pipe.raw")),
              HasSubstr("its data file 'pipe.raw' is not a regular file"));
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("folder")),
              HasSubstr("its data file 'folder' is not a regular file"));
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("-")),
              HasSubstr("its data file is '-' (standard input)"));
}

// A data file inside the folder that does not hold what the header says is not this header's.
TEST(FormatsNrrdHostile, DataFilesOfTheWrongSizeAreRefused) {
  TempDir dir;
  fs::create_directories(dir.path() / "study");
  const fs::path study = dir.path() / "study";
  test::writeBytes((study / "big.raw").string(), shorts(50, 0));
  test::writeBytes((study / "s0.raw").string(), shorts(12, 0));
  test::writeBytes((study / "s1.raw").string(), shorts(13, 0));
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("big.raw")),
              HasSubstr("its data file 'big.raw' holds 100 bytes where the header's sizes and "
                        "type need 48"));
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("LIST\ns0.raw\ns1.raw")),
              HasSubstr("its data file 's1.raw' holds 26 bytes where the header's sizes and "
                        "type need 24"));
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("s%d.raw 0 1 1")),
              HasSubstr("its data file 's1.raw' holds 26 bytes"));
  // With a byte skip the file holds more than the samples: at least that many.
  const std::string skip =
      "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\n"
      "encoding: raw\nbyte skip: 52\ndata file: big.raw\n";
  test::writeHeaderFile((study / "skip.nhdr").string(), skip);
  const Volume v = loadVolume((study / "skip.nhdr").string());
  EXPECT_EQ(v.toPhysical(v.at(0, 0, 0)), 26.0);
}

// Teem compares each key/value pair with every earlier one: 200,000 lines took over 120 s.
TEST(FormatsNrrdHostile, HeadersOfManyLinesAreRefusedQuickly) {
  TempDir dir;
  std::string many =
      "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\n"
      "encoding: raw\n";
  for (int i = 0; i < 200000; ++i) many += "key" + std::to_string(i) + ":=value\n";
  test::writeHeaderFile(dir.file("many.nrrd"), many + "\n", shorts(24, 0));
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THAT(loadError(dir.file("many.nrrd")),
              HasSubstr("the header has more than 4096 lines; Voxray reads headers of up to 4096"));
  EXPECT_LT(secondsSince(start), 5.0);
  // A header without its end within 1 MiB (one long line) is refused too.
  test::writeHeaderFile(dir.file("long.nrrd"),
                        "NRRD0004\ntype: short\n# " + std::string(2 << 20, 'x'));
  EXPECT_THAT(loadError(dir.file("long.nrrd")), HasSubstr("the header is longer than 1 MiB"));
  // Real headers with many key/value pairs (diffusion gradients) still open.
  std::string dwi =
      "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\n"
      "encoding: raw\n";
  for (int i = 0; i < 1000; ++i) dwi += "DWMRI_gradient_" + std::to_string(i) + ":=0 0 1\n";
  test::writeHeaderFile(dir.file("dwi.nrrd"), dwi + "\n", shorts(24, 0));
  const Volume v = loadVolume(dir.file("dwi.nrrd"));
  EXPECT_EQ(v.toPhysical(v.at(1, 1, 0)), 5.0);
}

// Teem quotes a field it cannot parse in a message it formats into 1 KiB: a field of about
// 1,000 characters ended in glibc's "buffer overflow detected" abort (the volume_file fuzz
// target found it with a long "space:"). Such fields are refused before Teem sees them, in
// every field and in a line without a colon; long comments and key/value pairs still open.
TEST(FormatsNrrdHostile, FieldsTooLongForTeemsMessagesAreRefused) {
  TempDir dir;
  const std::string start = "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\n";
  const std::string rest = "endian: little\nencoding: raw\n";
  const std::string longValue(1000, 'x');
  for (const std::string& line :
       {"space: " + longValue, "type: " + longValue, "space directions: " + longValue, longValue}) {
    test::writeHeaderFile(dir.file("long.nrrd"), start + line + "\n" + rest + "\n", shorts(24, 0));
    EXPECT_THAT(loadError(dir.file("long.nrrd")),
                HasSubstr("header line 5 is " + std::to_string(line.size()) +
                          " characters long; Voxray reads fields of up to 512"));
  }
  test::writeHeaderFile(dir.file("ok.nrrd"),
                        start + "# " + longValue + "\nnote:=" + longValue + "\n" + rest + "\n",
                        shorts(24, 3));
  const Volume v = loadVolume(dir.file("ok.nrrd"));
  EXPECT_EQ(v.dims, glm::ivec3(4, 3, 2));
  EXPECT_EQ(v.toPhysical(v.at(0, 0, 0)), 3.0);
}

// A field given twice (Teem leaked what it parsed of the first: LeakSanitizer, the
// volume_file fuzz target) is refused before Teem sees it, in either spelling.
TEST(FormatsNrrdHostile, FieldsGivenTwiceAreRefused) {
  TempDir dir;
  const std::string start = "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\n";
  test::writeHeaderFile(dir.file("twice.nrrd"),
                        start + "sizes: 4 3 2\nendian: little\nencoding: raw\n\n", shorts(24, 0));
  EXPECT_THAT(loadError(dir.file("twice.nrrd")),
              HasSubstr("the header gives the field 'sizes' twice; it is damaged"));
  test::writeHeaderFile(dir.file("spelled.nrrd"),
                        start +
                            "byte skip: 0\nbyteskip: 0\nendian: "
                            "little\nencoding: raw\n\n",
                        shorts(24, 0));
  EXPECT_THAT(loadError(dir.file("spelled.nrrd")),
              HasSubstr("the header gives the field 'byteskip' twice"));
  // Teem leaked its file list for a data file field before the sizes, or a list of none.
  fs::create_directories(dir.path() / "early");
  test::writeHeaderFile((dir.path() / "early" / "v.nhdr").string(),
                        "NRRD0004\ndata file: SKIPLIST\n");
  EXPECT_THAT(loadError((dir.path() / "early" / "v.nhdr").string()),
              HasSubstr("its data file field comes before the dimension and sizes"));
  EXPECT_THAT(nhdrError(dir, hostileNrrdHeader("LIST")),
              HasSubstr("its data file LIST names no file"));
}

}  // namespace
}  // namespace voxray
