// The raw dialog's model: the size check by the importer's rules and by how much it is off,
// the preview's value range with its HU hint, and the patient letters of the preview.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "raw_preview.h"
#include "voxray/io/orientation.h"

using namespace voxray;
using namespace voxray::ui;

namespace {

const std::string kCtHead = std::string(VOXRAY_DATA_DIR) + "/stanford/CThead";

RawLayout ctHeadLayout() {
  RawLayout l;
  l.dims = {256, 256, 0};
  l.type = SampleType::I16;
  l.order = ByteOrder::Big;
  return l;
}

// A raw file of N bytes of zeros in the test's temporary folder.
std::string zeros(const std::string& name, size_t n) {
  auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path, std::ios::binary) << std::string(n, '\0');
  return path.string();
}

}  // namespace

TEST(RawSizeCheck, SaysByHowManyBytesAndSlicesAFileIsOff) {
  RawLayout l = ctHeadLayout();
  l.dims.z = 4;  // 4 slices of 131072 bytes; the file holds 3 and a half
  std::string file = zeros("voxray_raw_size_check.raw", 131072 * 3 + 65536);
  RawSizeCheck c = checkRawSize(file, l);
  EXPECT_FALSE(c.matches());
  EXPECT_EQ(sizeMismatchText(c), "the file is 65536 bytes too short (0.50 slices)");
  l.dims.z = 2;
  EXPECT_EQ(sizeMismatchText(checkRawSize(file, l)),
            "the file is 196608 bytes too long (1.50 slices)");
  // Z = 0 takes the slices the file holds, which must be whole ones, as the importer says.
  l.dims.z = 0;
  EXPECT_FALSE(checkRawSize(file, l).matches());
  std::filesystem::resize_file(file, 131072 * 3);
  EXPECT_TRUE(checkRawSize(file, l).matches());
  EXPECT_EQ(sizeMismatchText(checkRawSize(file, l)), "");
  std::filesystem::remove(file);
}

TEST(RawSizeCheck, AFolderWithOtherThanZFilesDoesNotMatch) {
  RawLayout l = ctHeadLayout();
  EXPECT_TRUE(checkRawSize(kCtHead, l).matches());
  l.dims.z = 110;
  RawSizeCheck c = checkRawSize(kCtHead, l);
  EXPECT_FALSE(c.matches());
  EXPECT_EQ(sizeMismatchText(c),
            "the folder has 113 slice files, the layout 110 (3 file(s) too many)");
  l.dims = {256, 255, 0};
  EXPECT_EQ(sizeMismatchText(checkRawSize(kCtHead, l)), "the first file is 512 bytes too long");
}

TEST(RawPreview, ValueRangeIsRescaledAndHintsWhenItIsNotHu) {
  RawLayout l = ctHeadLayout();
  auto p = previewRawSlice(kCtHead, l);
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->image.width, 256);
  EXPECT_GE(p->lo, 0.0);  // CThead stores 0 for air: not HU
  EXPECT_GT(p->hi, 1000.0);
  std::string raw = valueRangeText(*p, l);
  EXPECT_NE(raw.find("not HU?"), std::string::npos) << raw;
  l.intercept = -1024.0;
  std::string hu = valueRangeText(*p, l);
  EXPECT_EQ(hu.find("not HU?"), std::string::npos) << hu;
  char expected[64];
  std::snprintf(expected, sizeof expected, "middle slice: %g … %g", p->lo - 1024.0, p->hi - 1024.0);
  EXPECT_EQ(hu, expected);
}

TEST(RawPreview, EdgeLettersFollowTheAxesCode) {
  EdgeLetters lpi = edgeLetters(directionFromAxesCode("LPI"));
  EXPECT_EQ(std::string({lpi.left, lpi.right, lpi.top, lpi.bottom, lpi.slices}), "RLAPI");
  EdgeLetters ras = edgeLetters(directionFromAxesCode("RAS"));
  EXPECT_EQ(std::string({ras.left, ras.right, ras.top, ras.bottom, ras.slices}), "LRPAS");
  EdgeLetters pil = edgeLetters(directionFromAxesCode("PIL"));
  EXPECT_EQ(std::string({pil.left, pil.right, pil.top, pil.bottom, pil.slices}), "APSIL");
}
