// The seed paper's raw datasets from shared/data, read as documented in its README.
#include <gtest/gtest.h>

#include "test_support.h"
#include "voxray/io/raw_import.h"

namespace voxray {
namespace {

using test::checksum;
using test::dataPath;

RawLayout stanfordLayout(SampleType type, double sliceMm) {
  RawLayout l;
  l.dims = {256, 256, 0};
  l.type = type;
  l.order = ByteOrder::Big;
  l.spacingMm = {1.0, 1.0, sliceMm};
  return l;
}

// 64-bit FNV-1a checksums of the whole volumes, computed once from the shared data.
constexpr uint64_t kCtHeadChecksum = 3707385581691363377ull;
constexpr uint64_t kMrBrainChecksum = 14387117486406892369ull;
constexpr uint64_t kCraniumChecksum = 2032638959512890162ull;
constexpr uint64_t kStentChecksum = 7635340286992146820ull;

TEST(RawRealData, CtHeadFolder) {
  const Volume v = importRaw(dataPath("stanford/CThead"), stanfordLayout(SampleType::I16, 2.0));
  EXPECT_EQ(v.dims, glm::ivec3(256, 256, 113));
  EXPECT_EQ(v.spacingMm, glm::dvec3(1.0, 1.0, 2.0));
  EXPECT_EQ(v.originMm, glm::dvec3(0.0));
  EXPECT_EQ(v.direction, glm::dmat3(1.0));
  EXPECT_EQ(v.slope, 1.0);
  EXPECT_EQ(v.intercept, 0.0);
  EXPECT_EQ(v.sourceType, "i16");
  EXPECT_EQ(v.unit, "value");  // no rescale given: nothing says these are HU
  EXPECT_TRUE(v.warnings.empty());
  const ValueRange r = storedRange(v);
  EXPECT_EQ(r.min, 0);
  EXPECT_EQ(r.max, 3272);
  EXPECT_EQ(checksum(v), kCtHeadChecksum);
}

TEST(RawRealData, CtHeadSlicesInNumericOrder) {
  const Volume v = importRaw(dataPath("stanford/CThead"), stanfordLayout(SampleType::I16, 2.0));
  // Text order would put CThead.100 at z = 2; numeric order puts CThead.10 at z = 9.
  for (int number : {2, 10, 100}) {
    const auto bytes =
        test::readBytes(dataPath("stanford/CThead/CThead." + std::to_string(number)));
    ASSERT_EQ(bytes.size(), 256u * 256u * 2u);
    int differences = 0, nonZero = 0;
    for (int y = 0; y < 256; ++y) {
      for (int x = 0; x < 256; ++x) {
        const size_t i = (size_t(y) * 256 + size_t(x)) * 2;
        const auto expected = int16_t(uint16_t(bytes[i] << 8 | bytes[i + 1]));
        differences += v.at(x, y, number - 1) != expected;
        nonZero += expected != 0;
      }
    }
    EXPECT_EQ(differences, 0) << "CThead." << number;
    EXPECT_GT(nonZero, 1000) << "CThead." << number << " should not be empty";
  }
}

TEST(RawRealData, CtHeadPatternMatchesFolder) {
  RawLayout l = stanfordLayout(SampleType::I16, 2.0);
  l.range = std::pair{1, 113};
  const Volume v = importRaw(dataPath("stanford/CThead/CThead.%d"), l);
  EXPECT_EQ(v.dims, glm::ivec3(256, 256, 113));
  EXPECT_EQ(checksum(v), kCtHeadChecksum);
}

TEST(RawRealData, CtHeadFolderRange) {
  RawLayout l = stanfordLayout(SampleType::I16, 2.0);
  l.range = std::pair{10, 20};
  const Volume part = importRaw(dataPath("stanford/CThead"), l);
  const Volume all = importRaw(dataPath("stanford/CThead"), stanfordLayout(SampleType::I16, 2.0));
  ASSERT_EQ(part.dims, glm::ivec3(256, 256, 11));
  EXPECT_EQ(part.at(100, 120, 0), all.at(100, 120, 9));
  EXPECT_EQ(part.at(130, 90, 10), all.at(130, 90, 19));
}

TEST(RawRealData, MrBrainUnsignedBigEndian) {
  const Volume v = importRaw(dataPath("stanford/MRbrain"), stanfordLayout(SampleType::U16, 1.5));
  EXPECT_EQ(v.dims, glm::ivec3(256, 256, 109));
  EXPECT_EQ(v.spacingMm, glm::dvec3(1.0, 1.0, 1.5));
  EXPECT_EQ(v.sourceType, "u16");
  EXPECT_EQ(v.slope, 1.0);
  EXPECT_EQ(v.intercept, 0.0);  // 1026..5119 fits 16-bit signed voxels as it is
  const ValueRange r = storedRange(v);
  EXPECT_EQ(r.min, 1026);
  EXPECT_EQ(r.max, 5119);
  EXPECT_EQ(checksum(v), kMrBrainChecksum);
}

TEST(RawRealData, CraniumSingleFileCountsSlices) {
  RawLayout l;
  l.dims = {256, 256, 0};
  l.type = SampleType::I16;
  l.order = ByteOrder::Little;
  l.spacingMm = {0.957, 0.957, 1.5};
  const Volume v = importRaw(dataPath("raw/cranium-ct/cranium_256x256x108_s16le.raw"), l);
  EXPECT_EQ(v.dims, glm::ivec3(256, 256, 108));
  EXPECT_EQ(v.spacingMm, glm::dvec3(0.957, 0.957, 1.5));
  const ValueRange r = storedRange(v);
  EXPECT_EQ(r.min, -1024);
  EXPECT_EQ(r.max, 2986);
  EXPECT_EQ(checksum(v), kCraniumChecksum);

  l.dims.z = 108;  // stated explicitly: the same volume
  EXPECT_EQ(checksum(importRaw(dataPath("raw/cranium-ct/cranium_256x256x108_s16le.raw"), l)),
            kCraniumChecksum);
}

TEST(RawRealData, StentRescaled) {
  RawLayout l;
  l.dims = {128, 128, 256};
  l.type = SampleType::U8;
  l.slope = 62.5;
  const std::string path = dataPath("raw/stent/stent_128x128x256_u8.raw");
  const Volume v = importRaw(path, l);
  EXPECT_EQ(v.dims, glm::ivec3(128, 128, 256));
  EXPECT_EQ(v.sourceType, "u8");
  const ValueRange r = storedRange(v);
  EXPECT_EQ(v.toPhysical(r.min), 0.0);
  EXPECT_EQ(v.toPhysical(r.max), 2000.0);  // 32 * 62.5
  EXPECT_EQ(checksum(v), kStentChecksum);
  // Every voxel within half a unit (the rounding) of raw * 62.5.
  const auto bytes = test::readBytes(path);
  ASSERT_EQ(bytes.size(), v.voxelCount());
  double worst = 0;
  for (size_t i = 0; i < bytes.size(); ++i) {
    worst = std::max(worst, std::abs(v.toPhysical(v.voxels[i]) - bytes[i] * 62.5));
  }
  EXPECT_LE(worst, 0.5);
}

}  // namespace
}  // namespace voxray
