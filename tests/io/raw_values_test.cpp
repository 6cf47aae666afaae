// How raw sample values become 16-bit voxels: byte order, headers, rescale, values that do
// not fit, NaN and infinity.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "test_support.h"
#include "voxray/io/raw_import.h"

namespace voxray {
namespace {

using testing::HasSubstr;

template <class T>
std::vector<uint8_t> bytesOf(const std::vector<T>& values, ByteOrder order) {
  std::vector<uint8_t> out(values.size() * sizeof(T));
  std::memcpy(out.data(), values.data(), out.size());
  if ((order == ByteOrder::Big) != (std::endian::native == std::endian::big)) {
    for (size_t i = 0; i < out.size(); i += sizeof(T)) {
      std::reverse(out.begin() + long(i), out.begin() + long(i + sizeof(T)));
    }
  }
  return out;
}

// Writes `values` as one raw file of dims (n, 1, 1) and reads it back.
template <class T>
Volume roundTrip(const std::vector<T>& values, SampleType type, ByteOrder order, double slope = 1,
                 double intercept = 0) {
  test::TempDir dir;
  test::writeBytes(dir.file("v.raw"), bytesOf(values, order));
  RawLayout l;
  l.dims = {int(values.size()), 1, 1};
  l.type = type;
  l.order = order;
  l.slope = slope;
  l.intercept = intercept;
  return importRaw(dir.file("v.raw"), l);
}

TEST(RawValues, ByteOrders) {
  const std::vector<int16_t> i16{-1024, 0, 1, 3071, -32768, 32767};
  for (ByteOrder order : {ByteOrder::Little, ByteOrder::Big}) {
    const Volume v = roundTrip(i16, SampleType::I16, order);
    EXPECT_EQ(v.voxels, i16);
  }
  const std::vector<float> f32{-1000.0f, 0.0f, 40.0f, 2000.0f};
  const Volume v = roundTrip(f32, SampleType::F32, ByteOrder::Big);
  EXPECT_EQ(v.slope, 1.0);  // whole numbers in range: stored as they are
  EXPECT_EQ(v.voxels, (std::vector<int16_t>{-1000, 0, 40, 2000}));
  EXPECT_EQ(v.sourceType, "f32");
}

TEST(RawValues, RescaleRoundsToWholeUnits) {
  const Volume v = roundTrip(std::vector<uint8_t>{0, 1, 2, 255}, SampleType::U8, ByteOrder::Little,
                             2.0, -1024.5);
  EXPECT_EQ(v.slope, 1.0);
  EXPECT_EQ(v.intercept, 0.0);
  EXPECT_EQ(v.voxels, (std::vector<int16_t>{-1024, -1022, -1020, -514}));  // half to even
}

TEST(RawValues, HeaderSkippedInEveryFile) {
  test::TempDir dir;
  for (int n : {1, 2}) {
    std::vector<uint8_t> bytes(8, 0xff);  // header
    const auto data = bytesOf(std::vector<uint16_t>{uint16_t(n), 500}, ByteOrder::Big);
    bytes.insert(bytes.end(), data.begin(), data.end());
    test::writeBytes(dir.file(std::string("s").append(std::to_string(n))), bytes);
  }
  RawLayout l;
  l.dims = {2, 1, 0};
  l.type = SampleType::U16;
  l.order = ByteOrder::Big;
  l.headerBytes = 8;
  const Volume v = importRaw(dir.path().string(), l);
  EXPECT_EQ(v.voxels, (std::vector<int16_t>{1, 500, 2, 500}));
}

TEST(RawValues, NanAndInfinityBecomeTheMinimum) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const Volume v = roundTrip(std::vector<float>{nan, -50.0f, 10.0f, inf, 300.0f, -inf},
                             SampleType::F32, ByteOrder::Little);
  ASSERT_EQ(v.warnings.size(), 1u);
  EXPECT_THAT(v.warnings[0], HasSubstr("3 voxels were NaN or infinite"));
  for (int x : {0, 3, 5}) EXPECT_EQ(v.toPhysical(v.at(x, 0, 0)), -50.0) << x;
  EXPECT_EQ(v.toPhysical(v.at(1, 0, 0)), -50.0);
  EXPECT_EQ(v.toPhysical(v.at(2, 0, 0)), 10.0);
  EXPECT_EQ(v.toPhysical(v.at(4, 0, 0)), 300.0);
}

TEST(RawValues, FractionalFloatsKeepTheirPrecision) {
  std::vector<float> values;
  for (int i = 0; i < 1000; ++i) values.push_back(float(std::sin(i * 0.01)));  // -1..1
  const Volume v = roundTrip(values, SampleType::F32, ByteOrder::Little);
  EXPECT_LT(v.slope, 1e-4);
  EXPECT_TRUE(v.warnings.empty());
  for (size_t i = 0; i < values.size(); ++i) {
    EXPECT_NEAR(v.toPhysical(v.voxels[i]), values[i], v.slope / 2 + 1e-9) << i;
  }
}

TEST(RawValues, UnsignedBeyondInt16IsShiftedNotClipped) {
  const std::vector<uint16_t> values{0, 1, 1000, 32767, 32768, 40000, 65534, 65535};
  const Volume v = roundTrip(values, SampleType::U16, ByteOrder::Little);
  ASSERT_EQ(v.warnings.size(), 1u);
  EXPECT_THAT(v.warnings[0], HasSubstr("do not fit 16-bit voxels"));
  EXPECT_EQ(v.slope, 1.0);
  for (size_t i = 0; i < values.size(); ++i) {
    EXPECT_NEAR(v.toPhysical(v.voxels[i]), values[i], 1.0) << values[i];
  }
}

TEST(RawValues, WideRangeGetsACoarserSlope) {
  // u16 * 3 spans 196605 units: more than 16 bits can hold in whole units.
  const std::vector<uint16_t> values{0, 100, 30000, 65535};
  const Volume v = roundTrip(values, SampleType::U16, ByteOrder::Little, 3.0, -1000.0);
  ASSERT_EQ(v.warnings.size(), 1u);
  EXPECT_THAT(v.warnings[0], HasSubstr("precision"));
  EXPECT_EQ(v.slope, 4.0);
  for (size_t i = 0; i < values.size(); ++i) {
    EXPECT_NEAR(v.toPhysical(v.voxels[i]), values[i] * 3.0 - 1000.0, v.slope / 2) << values[i];
  }
}

TEST(RawValues, SampleTypeNames) {
  for (SampleType t : {SampleType::U8, SampleType::I16, SampleType::U16, SampleType::F32}) {
    EXPECT_EQ(parseSampleType(toString(t)), t);
  }
  EXPECT_EQ(parseSampleType("INT16"), SampleType::I16);
  EXPECT_EQ(parseByteOrder("big"), ByteOrder::Big);
  EXPECT_EQ(parseByteOrder("little"), ByteOrder::Little);
}

}  // namespace
}  // namespace voxray
