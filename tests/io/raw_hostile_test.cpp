// Raw input that once hung Voxray (issue 19): a slice pattern with a range of two billion
// numbers, a FIFO given as input; and a folder of 100,000 slice files.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "test_support.h"
#include "voxray/io/load.h"
#include "voxray/io/raw_import.h"

namespace voxray {
namespace {

using test::errorMessage;
using testing::HasSubstr;

RawLayout layout2x2() {
  RawLayout l;
  l.dims = {2, 2, 0};
  l.type = SampleType::I16;
  return l;
}

TEST(RawHostile, HugePatternRangeStopsAtTheFirstGap) {
  test::TempDir dir;
  for (int n = 1; n <= 3; ++n)
    test::writeBytes(dir.file("s." + std::to_string(n)), std::vector<uint8_t>(8));
  RawLayout l = layout2x2();
  l.range = std::pair{1, 2000000000};
  // Once a walk over two billion names (over 60 s); now the gap after s.3 ends it, and the
  // message says how far it looked.
  EXPECT_THAT(errorMessage([&] { importRaw(dir.file("s.%d"), l); }),
              HasSubstr("slices 4-1004 missing after s.3"));
  l.range = std::pair{5, 2000000000};
  EXPECT_THAT(errorMessage([&] { importRaw(dir.file("s.%d"), l); }),
              HasSubstr("no files for slices 5-1005 (the first would be "));
}

class FifoInput : public testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0) << "cannot make a FIFO"; }
  test::TempDir dir;
  std::string fifo = dir.file("pipe");
};

TEST_F(FifoInput, RefusedAsRawFile) {
  EXPECT_THAT(errorMessage([&] { importRaw(fifo, layout2x2()); }),
              HasSubstr("pipe: is a FIFO (named pipe), not a regular file or folder"));
}

TEST_F(FifoInput, RefusedWhenNoLayoutIsGiven) {
  // The DICOM path used to block here forever, reading the FIFO's first bytes.
  EXPECT_THAT(errorMessage([&] { loadVolume(fifo); }), HasSubstr("is a FIFO (named pipe)"));
}

TEST_F(FifoInput, RefusedAsASliceOfAPattern) {
  test::writeBytes(dir.file("s.1"), std::vector<uint8_t>(8));
  std::filesystem::rename(fifo, dir.file("s.2"));
  RawLayout l = layout2x2();
  l.range = std::pair{1, 2};
  EXPECT_THAT(errorMessage([&] { importRaw(dir.file("s.%d"), l); }),
              HasSubstr("s.2: is a FIFO (named pipe)"));
}

TEST_F(FifoInput, SkippedInASliceFolder) {
  test::writeBytes(dir.file("s.1"), std::vector<uint8_t>(8));
  test::writeBytes(dir.file("s.2"), std::vector<uint8_t>(8));
  std::filesystem::rename(fifo, dir.file("s.3"));
  const Volume v = importRaw(dir.path().string(), layout2x2());
  EXPECT_EQ(v.dims, glm::ivec3(2, 2, 2));
}

TEST(RawHostile, FolderOf100000SlicesIsListedInNumberOrder) {
  // Sorting by number, not pairwise: the first wrong file is reported by number (s.1, not
  // s.10000 as text order would give) after listing all 100,000.
  test::TempDir dir;
  for (int n = 1; n <= 100000; ++n) std::ofstream(dir.file("s." + std::to_string(n)));
  EXPECT_THAT(errorMessage([&] { importRaw(dir.path().string(), layout2x2()); }),
              HasSubstr("s.1: expected 8 bytes (2x2 i16 + 0 header), found 0"));
}

}  // namespace
}  // namespace voxray
