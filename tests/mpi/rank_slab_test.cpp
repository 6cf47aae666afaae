// A rank's slab (app/mpi/rank_slab.h): importRaw with RawLayout::zSlab reads slices
// [first, end) alone, and placeSlab puts them back into the whole volume's geometry. Checked
// voxel for voxel against the whole import: the slab read must not change a value.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "rank_slab.h"
#include "voxray/io/error.h"
#include "voxray/io/raw_import.h"

namespace voxray::mpi {
namespace {

namespace fs = std::filesystem;

std::string ctHead() { return std::string(VOXRAY_DATA_DIR) + "/stanford/CThead"; }

LoadOptions ctHeadOptions() {
  RawLayout l;
  l.dims = {256, 256, 0};
  l.type = SampleType::I16;
  l.order = ByteOrder::Big;
  l.spacingMm = {1.0, 1.0, 2.0};
  LoadOptions o;
  o.raw = l;
  return o;
}

// A folder under the temp folder, gone at the end.
struct TempDir {
  fs::path path =
      fs::temp_directory_path() / ("voxray-mpi-slab-" + std::to_string(::getpid()) + "-" +
                                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

TEST(RankSlab, CtheadSlabEqualsTheWholeImportsSlices) {
  if (!fs::exists(ctHead())) GTEST_SKIP() << "CThead is not in ../shared/data";
  const LoadOptions o = ctHeadOptions();
  EXPECT_EQ(rawSlices(ctHead(), o), 113);
  const Volume whole = importRaw(ctHead(), *o.raw);
  PartRange r{57, 113, 53, 113};  // the upper of 2 parts with its apron of 4
  Volume slab = readSlab(ctHead(), o, r);
  ASSERT_EQ(slab.dims, glm::ivec3(256, 256, 60));
  // The slab's origin is its first slice's centre: 53 slices of 2 mm up the k axis.
  EXPECT_DOUBLE_EQ(slab.originMm.z, 106.0);
  EXPECT_EQ(slab.slope, whole.slope);
  EXPECT_EQ(slab.intercept, whole.intercept);
  const size_t sliceVoxels = 256 * 256;
  for (size_t i = 0; i < slab.voxels.size(); ++i)
    ASSERT_EQ(slab.voxels[i], whole.voxels[53 * sliceVoxels + i]) << "voxel " << i;

  const Volume placed = placeSlab(std::move(slab), r, 113, -5000);
  ASSERT_EQ(placed.dims, whole.dims);
  EXPECT_EQ(placed.originMm, whole.originMm);
  EXPECT_EQ(placed.spacingMm, whole.spacingMm);
  EXPECT_EQ(placed.voxels[0], -5000);                     // slice 0: filler
  EXPECT_EQ(placed.voxels[53 * sliceVoxels - 1], -5000);  // slice 52: filler
  for (size_t i = 53 * sliceVoxels; i < placed.voxels.size(); ++i)
    ASSERT_EQ(placed.voxels[i], whole.voxels[i]) << "voxel " << i;
}

// One raw file: the slab's bytes are found at their offset; slices outside it are not read
// (a file cut short after the slab still reads).
TEST(RankSlab, SingleFileSlabAndShortTail) {
  TempDir dir;
  const fs::path file = dir.path / "v.raw";
  std::vector<int16_t> values(4 * 3 * 10);
  for (size_t i = 0; i < values.size(); ++i) values[i] = int16_t(i);
  {
    std::ofstream f(file, std::ios::binary);
    f.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * 2));
  }
  LoadOptions o;
  o.raw = RawLayout{};
  o.raw->dims = {4, 3, 10};
  EXPECT_EQ(rawSlices(file.string(), o), 10);
  const Volume slab = readSlab(file.string(), o, PartRange{4, 6, 3, 7});
  ASSERT_EQ(slab.dims.z, 4);
  for (size_t i = 0; i < slab.voxels.size(); ++i) EXPECT_EQ(slab.voxels[i], int16_t(36 + i));
}

// A stack: only the slab's files are checked, so a broken file elsewhere is another rank's
// problem; one inside the slab is named.
TEST(RankSlab, StackChecksOnlyTheSlabsFiles) {
  TempDir dir;
  for (int k = 1; k <= 6; ++k) {
    std::vector<int16_t> slice(8 * 8, int16_t(10 * k));
    std::ofstream f(dir.path / ("s" + std::to_string(k) + ".raw"), std::ios::binary);
    f.write(reinterpret_cast<const char*>(slice.data()), k == 6 ? 10 : std::streamsize(128));
  }
  LoadOptions o;
  o.raw = RawLayout{};
  o.raw->dims = {8, 8, 0};
  EXPECT_EQ(rawSlices(dir.path.string(), o), 6);
  const Volume low = readSlab(dir.path.string(), o, PartRange{0, 3, 0, 5});
  EXPECT_EQ(low.dims.z, 5);
  EXPECT_EQ(low.voxels.back(), 50);
  try {
    readSlab(dir.path.string(), o, PartRange{3, 6, 1, 6});
    FAIL() << "a short file in the slab was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("s6.raw: expected 128 bytes"), std::string::npos)
        << e.what();
  }
}

TEST(RankSlab, SlabOutsideTheStackIsRefused) {
  if (!fs::exists(ctHead())) GTEST_SKIP() << "CThead is not in ../shared/data";
  try {
    readSlab(ctHead(), ctHeadOptions(), PartRange{100, 120, 96, 120});
    FAIL() << "slices beyond the stack were read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("slices 96 to 119 were asked for, but it holds slices "
                                         "0 to 112"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace voxray::mpi
