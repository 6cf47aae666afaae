// The SIEMENS CSA image header reader (siemens_mosaic.h) on headers built here: the two values
// the mosaic split needs, and damaged headers (cut short anywhere, absurd counts) read as
// "not given", never past their end.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "siemens_mosaic.h"

namespace voxray::dicom {
namespace {

using Tags = std::vector<std::pair<std::string, std::vector<std::string>>>;

void u32(std::vector<uint8_t>& out, uint32_t v) {
  for (int b = 0; b < 4; ++b) out.push_back(uint8_t(v >> (8 * b)));
}

// CSA2: "SV10" \4\3\2\1, tag count, 77; per tag name[64], VM, VR[4], SyngoDT, items, 77; per
// item four words (the second its length), then the text padded to 4 bytes.
std::vector<uint8_t> csa(const Tags& tags, uint32_t itemsOverride = 0) {
  std::vector<uint8_t> out = {'S', 'V', '1', '0', 4, 3, 2, 1};
  u32(out, uint32_t(tags.size()));
  u32(out, 77);
  for (const auto& [name, items] : tags) {
    std::string field = name;
    field.resize(64, '\0');
    out.insert(out.end(), field.begin(), field.end());
    u32(out, uint32_t(items.size()));
    out.insert(out.end(), {'D', 'S', 0, 0});
    u32(out, 3);
    u32(out, itemsOverride ? itemsOverride : uint32_t(items.size()));
    u32(out, 77);
    for (const std::string& item : items) {
      const uint32_t length = uint32_t(item.size() + 1);
      for (uint32_t w : {length, length, 77u, length}) u32(out, w);
      out.insert(out.end(), item.begin(), item.end());
      out.resize(out.size() + 1 + (4 - length % 4) % 4, 0);
    }
  }
  return out;
}

const Tags kTags = {{"EchoLinePosition", {"32", "", ""}},
                    {"NumberOfImagesInMosaic", {"36 "}},
                    {"SliceNormalVector", {"0.0", "0.1079993545", "0.9941509641"}}};

TEST(CsaHeader, ReadsTheMosaicCountAndTheSliceNormal) {
  const std::vector<uint8_t> bytes = csa(kTags);
  const CsaImageInfo info = parseCsaImageHeader(bytes.data(), bytes.size());
  ASSERT_TRUE(info.imagesInMosaic);
  EXPECT_EQ(*info.imagesInMosaic, 36);
  ASSERT_TRUE(info.sliceNormal);
  EXPECT_DOUBLE_EQ(info.sliceNormal->y, 0.1079993545);
  EXPECT_DOUBLE_EQ(info.sliceNormal->z, 0.9941509641);
}

// Cut at every length (each copied to a buffer of exactly that size, so a read past it is a
// heap overflow the sanitizer build reports): what is read is right or absent.
TEST(CsaHeader, ACutHeaderIsReadOnlyAsFarAsItGoes) {
  const std::vector<uint8_t> bytes = csa(kTags);
  size_t withCount = 0;
  for (size_t n = 0; n < bytes.size(); ++n) {
    std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + ptrdiff_t(n));
    const CsaImageInfo info = parseCsaImageHeader(cut.data(), cut.size());
    if (info.imagesInMosaic) {
      EXPECT_EQ(*info.imagesInMosaic, 36) << n;
      ++withCount;
    }
    if (info.sliceNormal) {
      EXPECT_DOUBLE_EQ(info.sliceNormal->z, 0.9941509641) << n;
      // The last item's text ends 3 bytes (its padding) before the header's end.
      EXPECT_GE(n, bytes.size() - 3);
    }
  }
  EXPECT_GT(withCount, 0u);  // from the end of its item on
}

TEST(CsaHeader, AbsurdCountsAndOtherLayoutsGiveNothing) {
  std::vector<uint8_t> many = csa(kTags, 0x7fffffff);
  EXPECT_FALSE(parseCsaImageHeader(many.data(), many.size()).imagesInMosaic);
  std::vector<uint8_t> tags = csa(kTags);
  tags[8] = 0xff;  // 255 tags: more than the 128 a header may have
  EXPECT_FALSE(parseCsaImageHeader(tags.data(), tags.size()).imagesInMosaic);
  std::vector<uint8_t> csa1 = csa(kTags);
  std::memcpy(csa1.data(), "XX10", 4);  // not CSA2
  EXPECT_FALSE(parseCsaImageHeader(csa1.data(), csa1.size()).imagesInMosaic);
  EXPECT_FALSE(parseCsaImageHeader(nullptr, 0).imagesInMosaic);
  // A length past the end of the header.
  std::vector<uint8_t> longItem = csa({{"NumberOfImagesInMosaic", {"36"}}});
  longItem[16 + 84 + 4] = 0xff;
  longItem[16 + 84 + 5] = 0xff;
  EXPECT_FALSE(parseCsaImageHeader(longItem.data(), longItem.size()).imagesInMosaic);
}

}  // namespace
}  // namespace voxray::dicom
