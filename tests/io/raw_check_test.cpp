// The raw size check the import dialog shows while the user types: by how much an input is
// off, and, for every layout, the same verdict as the importer (one rule in io).
#include <filesystem>

#include "test_support.h"
#include "voxray/io/raw_check.h"

namespace voxray {
namespace {

using test::dataPath;
using test::TempDir;

const std::string kCtHead = dataPath("stanford/CThead");

std::string zeros(const TempDir& dir, const std::string& name, size_t n) {
  test::writeBytes(dir.file(name), std::vector<uint8_t>(n, 0));
  return dir.file(name);
}

// True when the importer accepts INPUT as LAYOUT (its size rules are the ones under test).
bool importerAccepts(const std::string& input, const RawLayout& l) {
  try {
    importRaw(input, l);
    return true;
  } catch (const Error&) {
    return false;
  }
}

TEST(RawSizeCheck, SaysByHowManyBytesAndSlicesAFileIsOff) {
  TempDir dir;
  RawLayout l = test::ctHeadFolderLayout();
  l.dims.z = 4;  // 4 slices of 131072 bytes; the file holds 3 and a half
  std::string file = zeros(dir, "size_check.raw", 131072 * 3 + 65536);
  RawSizeCheck c = checkRawSize(file, l);
  EXPECT_FALSE(c.matches());
  EXPECT_EQ(c.expectedBytes, 4u * 131072u);
  EXPECT_EQ(c.actualBytes, 3u * 131072u + 65536u);
  EXPECT_EQ(sizeMismatchText(c), "the file is 65536 bytes too short (0.50 slices)");
  l.dims.z = 2;
  EXPECT_EQ(sizeMismatchText(checkRawSize(file, l)),
            "the file is 196608 bytes too long (1.50 slices)");
  // Z = 0 takes the slices the file holds, which must be whole ones.
  l.dims.z = 0;
  EXPECT_FALSE(checkRawSize(file, l).matches());
  std::filesystem::resize_file(file, 131072 * 3);
  EXPECT_TRUE(checkRawSize(file, l).matches());
  EXPECT_EQ(sizeMismatchText(checkRawSize(file, l)), "");
}

TEST(RawSizeCheck, AFolderWithOtherThanZFilesDoesNotMatch) {
  RawLayout l = test::ctHeadFolderLayout();
  EXPECT_TRUE(checkRawSize(kCtHead, l).matches());
  l.dims.z = 110;
  RawSizeCheck c = checkRawSize(kCtHead, l);
  EXPECT_FALSE(c.matches());
  EXPECT_EQ(sizeMismatchText(c),
            "the folder has 113 slice files, the layout 110 (3 file(s) too many)");
  l.dims = {256, 255, 0};
  EXPECT_EQ(sizeMismatchText(checkRawSize(kCtHead, l)), "CThead.1 is 512 bytes too long");
  // --raw-range limits the files, as the importer does.
  l.dims = {256, 256, 10};
  l.range = std::pair{1, 10};
  EXPECT_TRUE(checkRawSize(kCtHead, l).matches());
}

// Issue 41 item 8: the dialog checks a pattern as the importer reads it, its range found
// by listing its folder; and a folder of 001.tif ... is a stack.
TEST(RawSizeCheck, PatternAndNumberedNamesWithAnExtension) {
  TempDir dir;
  for (int k = 1; k <= 3; ++k) zeros(dir, "00" + std::to_string(k) + ".tif", 32);
  RawLayout l;
  l.dims = {4, 4, 0};
  for (const std::string& input : {dir.file("%03d.tif"), dir.path().string()}) {
    RawSizeCheck c = checkRawSize(input, l);
    EXPECT_TRUE(c.matches()) << input << ": " << c.problem;
    EXPECT_EQ(c.files, 3) << input;
    ASSERT_TRUE(readMiddleRawSlice(input, l).has_value()) << input;
  }
  l.dims = {4, 3, 0};
  EXPECT_EQ(sizeMismatchText(checkRawSize(dir.file("%03d.tif"), l)), "001.tif is 8 bytes too long");
}

// One short file in the middle of a stack: the check names it, as the importer does.
TEST(RawSizeCheck, NamesTheFirstSliceFileWhoseSizeIsOff) {
  TempDir dir;
  for (int k = 1; k <= 3; ++k) zeros(dir, "s." + std::to_string(k), k == 2 ? 30 : 32);
  RawLayout l;
  l.dims = {4, 4, 0};
  RawSizeCheck c = checkRawSize(dir.path().string(), l);
  EXPECT_FALSE(c.matches());
  EXPECT_EQ(c.file, "s.2");
  EXPECT_EQ(sizeMismatchText(c), "s.2 is 2 bytes too short");
}

TEST(RawSizeCheck, AFolderThatCannotBeAStackSaysWhy) {
  TempDir dir;
  zeros(dir, "s.1", 32);
  zeros(dir, "s.3", 32);
  RawLayout l;
  l.dims = {4, 4, 0};
  RawSizeCheck c = checkRawSize(dir.path().string(), l);
  EXPECT_EQ(c.files, 0);
  EXPECT_THAT(sizeMismatchText(c), testing::HasSubstr("slice 2 missing between s.1 and s.3"));
  EXPECT_EQ(sizeMismatchText(checkRawSize(dir.file("nothing"), l)), "no such file or folder");
}

// The dialog enables Open exactly when the importer would take the input: the same verdict
// on files, folders, headers and Z = 0 over a grid of layouts.
TEST(RawSizeCheck, AgreesWithTheImporterOnEveryLayout) {
  TempDir dir;
  const std::string file = zeros(dir, "v.raw", 4 * 4 * 2 * 3 + 8);  // 3 i16 slices + 8 bytes
  const std::string stack = (dir.path() / "stack").string();
  std::filesystem::create_directories(stack);
  for (int k = 1; k <= 3; ++k) zeros(dir, "stack/s." + std::to_string(k), 4 * 4 * 2 + 8);
  int accepted = 0, cases = 0;
  for (const std::string& input : {file, stack})
    for (int x : {2, 4, 8})
      for (int z : {0, 1, 2, 3, 4})
        for (size_t header : {size_t(0), size_t(8), size_t(16)})
          for (SampleType t : {SampleType::U8, SampleType::I16}) {
            RawLayout l;
            l.dims = {x, 4, z};
            l.headerBytes = header;
            l.type = t;
            const bool check = checkRawSize(input, l).matches();
            EXPECT_EQ(check, importerAccepts(input, l))
                << input << " x=" << x << " z=" << z << " header=" << header
                << " type=" << toString(t);
            accepted += check;
            ++cases;
          }
  // The grid holds both verdicts: the file as 4x4x3 i16 + 8, the stack likewise, and a few
  // u8 layouts that happen to fit (4x4x6 u8 + 8 ...).
  EXPECT_EQ(cases, 180);
  EXPECT_GE(accepted, 4);
  EXPECT_LT(accepted, 20);
}

TEST(RawMiddleSlice, ReadsTheMiddleSliceBeforeTheRescale) {
  RawLayout l = test::ctHeadFolderLayout();
  l.slope = 2.0;  // must not apply: the preview shows the raw values
  auto values = readMiddleRawSlice(kCtHead, l);
  ASSERT_TRUE(values.has_value());
  ASSERT_EQ(values->size(), 256u * 256u);
  // CThead's raw values run 0 ... 3272 (shared data README); the middle slice has both ends.
  auto [lo, hi] = std::minmax_element(values->begin(), values->end());
  EXPECT_GE(*lo, 0.0);
  EXPECT_LE(*hi, 3272.0);
  EXPECT_GT(*hi, 1000.0);
  Volume v = importRaw(kCtHead, test::ctHeadFolderLayout());
  const int mid = v.dims.z / 2;
  EXPECT_EQ((*values)[size_t(128) * 256 + 100], double(v.at(100, 128, mid)));
  l.dims.x = 257;  // longer than a slice file
  EXPECT_FALSE(readMiddleRawSlice(kCtHead, l).has_value());
}

}  // namespace
}  // namespace voxray
