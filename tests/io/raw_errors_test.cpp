// Bad raw input must be refused with a message that names the file, says what is wrong
// and what to change.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_support.h"
#include "voxray/io/raw_import.h"

namespace voxray {
namespace {

using test::dataPath;
using test::errorMessage;
using testing::HasSubstr;

const std::string kCranium = "raw/cranium-ct/cranium_256x256x108_s16le.raw";

RawLayout i16Layout(int x, int y, int z) {
  RawLayout l;
  l.dims = {x, y, z};
  l.type = SampleType::I16;
  return l;
}

// A stack of 4x4 i16 slices named <name>.<number>, one file per number.
void writeStack(const test::TempDir& dir, const std::string& name,
                std::initializer_list<int> numbers) {
  for (int n : numbers)
    test::writeBytes(dir.file(name + "." + std::to_string(n)),
                     std::vector<uint8_t>(32, uint8_t(n)));
}

TEST(RawErrors, TruncatedSliceInStack) {
  test::TempDir dir;
  test::writeBytes(dir.file("CThead.1"), std::vector<uint8_t>(131072));
  test::writeBytes(dir.file("CThead.2"), std::vector<uint8_t>(131000));
  test::writeBytes(dir.file("CThead.3"), std::vector<uint8_t>(131072));
  const std::string m =
      errorMessage([&] { importRaw(dir.path().string(), i16Layout(256, 256, 0)); });
  EXPECT_THAT(m,
              HasSubstr("CThead.2: expected 131072 bytes (256x256 i16 + 0 header), found 131000"));
  EXPECT_THAT(m, HasSubstr("--raw-dims"));
}

TEST(RawErrors, TruncatedSingleFile) {
  test::TempDir dir;
  test::writeBytes(dir.file("short.raw"), std::vector<uint8_t>(4 * 4 * 3 * 2 - 1));
  const std::string m = errorMessage([&] { importRaw(dir.file("short.raw"), i16Layout(4, 4, 3)); });
  EXPECT_THAT(m, HasSubstr("short.raw: expected 96 bytes (4x4x3 i16 + 0 header), found 95"));
}

TEST(RawErrors, WrongDimsForSingleFile) {
  const std::string m =
      errorMessage([&] { importRaw(dataPath(kCranium), i16Layout(256, 256, 100)); });
  EXPECT_THAT(m, HasSubstr("cranium_256x256x108_s16le.raw: expected 13107200 bytes "
                           "(256x256x100 i16 + 0 header), found 14155776"));
}

TEST(RawErrors, WrongDimsForStack) {
  const std::string m =
      errorMessage([&] { importRaw(dataPath("stanford/CThead"), i16Layout(512, 512, 0)); });
  EXPECT_THAT(m,
              HasSubstr("CThead.1: expected 524288 bytes (512x512 i16 + 0 header), found 131072"));
}

TEST(RawErrors, FileNotWholeSlices) {
  const std::string m =
      errorMessage([&] { importRaw(dataPath(kCranium), i16Layout(300, 300, 0)); });
  EXPECT_THAT(m, HasSubstr("14155776 bytes are not a whole number of 300x300 slices"));
}

TEST(RawErrors, HeaderCountsInExpectedSize) {
  RawLayout l = i16Layout(256, 256, 108);
  l.headerBytes = 16;
  const std::string m = errorMessage([&] { importRaw(dataPath(kCranium), l); });
  EXPECT_THAT(m, HasSubstr("expected 14155792 bytes (256x256x108 i16 + 16 header)"));
}

TEST(RawErrors, MissingSliceInFolder) {
  test::TempDir dir;
  writeStack(dir, "s", {1, 2, 4});
  const std::string m = errorMessage([&] { importRaw(dir.path().string(), i16Layout(4, 4, 0)); });
  EXPECT_THAT(m, HasSubstr("slice 3 missing between s.2 and s.4"));
}

TEST(RawErrors, MissingSlicesInPattern) {
  test::TempDir dir;
  writeStack(dir, "s", {1, 2, 5});
  RawLayout l = i16Layout(4, 4, 0);
  l.range = std::pair{1, 5};
  const std::string m = errorMessage([&] { importRaw(dir.file("s.%d"), l); });
  EXPECT_THAT(m, HasSubstr("slices 3-4 missing between s.2 and s.5"));
}

TEST(RawErrors, MissingSliceAtStartOfRange) {
  test::TempDir dir;
  writeStack(dir, "s", {2, 3});
  RawLayout l = i16Layout(4, 4, 0);
  l.range = std::pair{1, 3};
  EXPECT_THAT(errorMessage([&] { importRaw(dir.path().string(), l); }),
              HasSubstr("slice 1 missing before s.2"));
}

TEST(RawErrors, RangeAvoidsTheGap) {
  test::TempDir dir;
  writeStack(dir, "s", {1, 2, 4});
  RawLayout l = i16Layout(4, 4, 0);
  l.range = std::pair{1, 2};
  const Volume v = importRaw(dir.path().string(), l);
  EXPECT_EQ(v.dims, glm::ivec3(4, 4, 2));
  EXPECT_EQ(v.at(0, 0, 1), int16_t(0x0202));
}

TEST(RawErrors, DuplicateSliceNumbers) {
  test::TempDir dir;
  writeStack(dir, "s", {1, 2});
  test::writeBytes(dir.file("s.01"), std::vector<uint8_t>(32));
  EXPECT_THAT(errorMessage([&] { importRaw(dir.path().string(), i16Layout(4, 4, 0)); }),
              HasSubstr("both have slice number 1"));
}

TEST(RawErrors, SliceCountDiffersFromDims) {
  test::TempDir dir;
  writeStack(dir, "s", {1, 2, 3});
  EXPECT_THAT(errorMessage([&] { importRaw(dir.path().string(), i16Layout(4, 4, 5)); }),
              HasSubstr("the stack has 3 slice files but --raw-dims gives 5 slices"));
}

TEST(RawErrors, ZeroAndNegativeDims) {
  EXPECT_THAT(errorMessage([&] { importRaw(dataPath(kCranium), i16Layout(0, 256, 108)); }),
              HasSubstr("raw dimensions 0x256x108 are not valid"));
  EXPECT_THAT(errorMessage([&] { importRaw(dataPath(kCranium), i16Layout(256, 256, -1)); }),
              HasSubstr("are not valid"));
}

TEST(RawErrors, AbsurdDimsRefusedBeforeAllocating) {
  // 10^15 voxels: must be refused from the numbers alone, not by running out of memory.
  EXPECT_THAT(
      errorMessage([&] { importRaw(dataPath(kCranium), i16Layout(100000, 100000, 100000)); }),
      HasSubstr("100000x100000x100000 are more than the 8589934592 voxels"));
  EXPECT_THAT(errorMessage([&] { importRaw(dataPath(kCranium), i16Layout(2048, 2048, 1 << 30)); }),
              HasSubstr("are more than"));
  RawLayout l = i16Layout(65536, 65536, 0);
  l.range = std::pair{0, 2000000000};
  EXPECT_THAT(errorMessage([&] { importRaw(dataPath("stanford/CThead/CThead.%d"), l); }),
              HasSubstr("are more than"));
}

// Issue 41 item 8: a pattern without --raw-range was refused; its folder tells the range.
// 0013.tif (four digits) is not %03d's and 999.txt is not .tif: neither widens it.
TEST(RawErrors, PatternFindsItsRangeInItsFolder) {
  test::TempDir dir;
  for (int n = 7; n <= 12; ++n) {
    char name[16];
    std::snprintf(name, sizeof name, "%03d.tif", n);
    test::writeBytes(dir.file(name), std::vector<uint8_t>(32, uint8_t(n)));
  }
  test::writeBytes(dir.file("0013.tif"), std::vector<uint8_t>(32));
  test::writeBytes(dir.file("999.txt"), std::vector<uint8_t>(32));
  const Volume v = importRaw(dir.file("%03d.tif"), i16Layout(4, 4, 0));
  EXPECT_EQ(v.dims, glm::ivec3(4, 4, 6));
  EXPECT_EQ(v.at(0, 0, 0), int16_t(0x0707));
  EXPECT_EQ(v.at(3, 3, 5), int16_t(0x0c0c));
  // A gap inside the listed range is still a missing slice, not a shorter stack.
  std::filesystem::remove(dir.file("009.tif"));
  EXPECT_THAT(errorMessage([&] { importRaw(dir.file("%03d.tif"), i16Layout(4, 4, 0)); }),
              HasSubstr("slice 9 missing between 008.tif and 010.tif"));
  // Nothing matches: the message says so, and how to give the numbers.
  EXPECT_THAT(errorMessage([&] { importRaw(dir.file("img%d.raw"), i16Layout(4, 4, 0)); }),
              HasSubstr("no file in " + dir.path().string() +
                        " matches it; give the slice numbers with --raw-range FIRST-LAST"));
}

// Issue 41 item 8: a folder of 001.tif ... was refused ("no slice files in this folder").
// The number before a short extension counts; the largest group of one ending is the stack.
TEST(RawErrors, FolderOfNumberedNamesWithAnExtension) {
  test::TempDir dir;
  for (int n = 1; n <= 5; ++n) {
    char name[16];
    std::snprintf(name, sizeof name, "%03d.tif", n);
    test::writeBytes(dir.file(name), std::vector<uint8_t>(32, uint8_t(n)));
  }
  test::writeBytes(dir.file("notes2.txt"), {'h', 'i'});  // numbered too, but alone
  test::writeBytes(dir.file("readme"), {'h', 'i'});
  const Volume v = importRaw(dir.path().string(), i16Layout(4, 4, 0));
  EXPECT_EQ(v.dims, glm::ivec3(4, 4, 5));
  EXPECT_EQ(v.at(0, 0, 4), int16_t(0x0505));
  // Two endings with as many files: which is the stack is not guessed.
  for (int n = 1; n <= 5; ++n) test::writeBytes(dir.file(std::to_string(n) + ".raw"), {0, 0});
  EXPECT_THAT(errorMessage([&] { importRaw(dir.path().string(), i16Layout(4, 4, 0)); }),
              HasSubstr("5 numbered files each with .raw and .tif: which are the slices?"));
}

TEST(RawErrors, BadPatternAndRange) {
  RawLayout l = i16Layout(256, 256, 0);
  l.range = std::pair{1, 3};
  EXPECT_THAT(errorMessage([&] { importRaw("/nonexistent/slice%s", l); }),
              HasSubstr("exactly one %d or %0Nd"));
  EXPECT_THAT(errorMessage([&] { importRaw("/nonexistent/slice%d_%d", l); }),
              HasSubstr("exactly one %d or %0Nd"));
  l.range = std::pair{5, 3};
  EXPECT_THAT(errorMessage([&] { importRaw(dataPath("stanford/CThead/CThead.%d"), l); }),
              HasSubstr("slice range 5-3"));
}

TEST(RawErrors, ZeroPaddedPattern) {
  test::TempDir dir;
  for (int n : {7, 8, 9, 10}) {
    char name[16];
    std::snprintf(name, sizeof name, "img%03d.raw", n);
    test::writeBytes(dir.file(name), std::vector<uint8_t>(32, uint8_t(n)));
  }
  RawLayout l = i16Layout(4, 4, 0);
  l.range = std::pair{7, 10};
  const Volume v = importRaw(dir.file("img%03d.raw"), l);
  EXPECT_EQ(v.dims, glm::ivec3(4, 4, 4));
  EXPECT_EQ(v.at(3, 3, 3), int16_t(0x0a0a));
}

TEST(RawErrors, UnknownNames) {
  const std::string m = errorMessage([] { parseSampleType("i32"); });
  EXPECT_THAT(m, HasSubstr("unknown sample type 'i32'"));
  EXPECT_THAT(m, HasSubstr("u8, i16, u16 or f32"));
  EXPECT_THAT(errorMessage([] { parseByteOrder("middle"); }), HasSubstr("use big or little"));
}

TEST(RawErrors, MissingPathAndEmptyFolder) {
  EXPECT_THAT(errorMessage([&] { importRaw("/nonexistent/volume.raw", i16Layout(4, 4, 0)); }),
              HasSubstr("/nonexistent/volume.raw: no such file or folder"));
  test::TempDir dir;
  test::writeBytes(dir.file("notes.txt"), {1, 2, 3});
  EXPECT_THAT(errorMessage([&] { importRaw(dir.path().string(), i16Layout(4, 4, 0)); }),
              HasSubstr("no slice files in this folder"));
}

TEST(RawErrors, BadSpacing) {
  RawLayout l = i16Layout(256, 256, 0);
  l.spacingMm.z = 0;
  EXPECT_THAT(errorMessage([&] { importRaw(dataPath(kCranium), l); }),
              HasSubstr("spacing must be positive"));
  l.spacingMm.z = std::nan("");
  EXPECT_THAT(errorMessage([&] { importRaw(dataPath(kCranium), l); }),
              HasSubstr("spacing must be positive"));
}

TEST(RawErrors, UnreadableFile) {
  test::TempDir dir;
  test::writeBytes(dir.file("locked.raw"), std::vector<uint8_t>(32));
  std::filesystem::permissions(dir.file("locked.raw"), std::filesystem::perms::none);
  if (std::ifstream(dir.file("locked.raw")).good()) GTEST_SKIP() << "running as root";
  EXPECT_THAT(errorMessage([&] { importRaw(dir.file("locked.raw"), i16Layout(4, 4, 1)); }),
              HasSubstr("locked.raw: cannot read"));
}

}  // namespace
}  // namespace voxray
