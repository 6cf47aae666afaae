// Uncompressed little-endian 16-bit frames are read straight into the volume (NativeFrames,
// storeWords), in either VR encoding and wherever the pixel data lies in the file; every
// other file takes the general decoder (PixelFile, storeSlice). A deflated file with the
// same pixels takes the general one, so the paths are compared on every 16-bit word, for
// each stored sample format, with and without padding: bit for bit.
#include <gtest/gtest.h>

#include <optional>

#include "../io/test_support.h"
#include "dicom_writer.h"
#include "test_data.h"

namespace voxray {
namespace {

struct Format {
  const char* name;
  int bitsStored, pixelRepresentation;
  std::optional<int> padding, paddingLimit;
};

enum class Encoding {
  Explicit,         // explicit VR little endian, the pixel data last
  Implicit,         // implicit VR little endian
  TrailingElement,  // an element after the pixel data
  Deflated,         // the general decoder
};

// Three 256x256 CT slices (z 0, 1, 2; fewer is no volume): slice 0 holds word i at pixel i,
// slice 1 its inverse, slice 2 word i XOR 0x5A5A.
Volume importEveryWord(const Format& f, Encoding encoding = Encoding::Explicit) {
  test::TempDir dir;
  for (int k = 0; k < 3; ++k) {
    test::TestSlice s;
    s.size = 256;
    s.allWords = true;
    s.wordXor = uint16_t(k == 0 ? 0 : k == 1 ? 0xFFFF : 0x5A5A);
    s.z = k;
    s.instance = k + 1;
    s.bitsStored = f.bitsStored;
    s.pixelRepresentation = f.pixelRepresentation;
    s.padding = f.padding;
    s.paddingLimit = f.paddingLimit;
    s.deflated = encoding == Encoding::Deflated;
    s.implicitVr = encoding == Encoding::Implicit;
    s.trailingPadding = encoding == Encoding::TrailingElement;
    test::writeTestSlice(dir.file(std::to_string(k) + ".dcm"), s);
  }
  return importDicom(dir.path().string());
}

const Format kFormats[] = {
    {"i16", 16, 1, {}, {}},
    {"u16", 16, 0, {}, {}},
    {"i12", 12, 1, {}, {}},
    {"u12", 12, 0, {}, {}},
    {"i16 padding -2000", 16, 1, -2000, {}},
    {"u16 padding 0..100", 16, 0, 0, 100},
    {"i12 padding -2048..-1000", 12, 1, -1000, -2048},
    {"u12 padding 4095", 12, 0, 4095, {}},
};

TEST(DicomNativeFrames, EveryWordImportsAsTheGeneralDecoderImportsIt) {
  for (const Format& f : kFormats) {
    SCOPED_TRACE(f.name);
    const Volume general = importEveryWord(f, Encoding::Deflated);
    ASSERT_EQ(general.dims, glm::ivec3(256, 256, 3));
    for (Encoding e : {Encoding::Explicit, Encoding::Implicit, Encoding::TrailingElement}) {
      SCOPED_TRACE(int(e));
      const Volume direct = importEveryWord(f, e);
      ASSERT_EQ(direct.dims, general.dims);
      EXPECT_EQ(direct.slope, general.slope);
      EXPECT_EQ(direct.intercept, general.intercept);
      EXPECT_TRUE(direct.voxels == general.voxels);
    }
  }
}

// The values themselves (intercept 0, slope 1 in every file; CT padding becomes -1024 HU).
TEST(DicomNativeFrames, StoredWordsMeanWhatTheirFormatSays) {
  auto hu = [](const Volume& v, uint16_t word) {
    return v.toPhysical(v.at(word % 256, word / 256, 0));
  };
  const Volume i16 = importEveryWord(kFormats[0]);
  EXPECT_EQ(hu(i16, 0x7FFF), 32767.0);
  EXPECT_EQ(hu(i16, 0x8000), -32768.0);
  EXPECT_EQ(hu(i16, 0xFFFF), -1.0);
  const Volume u16 = importEveryWord(kFormats[1]);
  EXPECT_EQ(u16.intercept, 32768.0);  // shifted, not clipped
  EXPECT_EQ(hu(u16, 0x0000), 0.0);
  EXPECT_EQ(hu(u16, 0xFFFF), 65535.0);
  const Volume i12 = importEveryWord(kFormats[2]);
  EXPECT_EQ(hu(i12, 0x0FFF), -1.0);     // 12 bits, sign-extended
  EXPECT_EQ(hu(i12, 0xF800), -2048.0);  // bits above BitsStored ignored
  EXPECT_EQ(hu(i12, 0x07FF), 2047.0);
  const Volume u12 = importEveryWord(kFormats[3]);
  EXPECT_EQ(hu(u12, 0xF123), 0x123);
  const Volume pad = importEveryWord(kFormats[4]);
  EXPECT_EQ(hu(pad, uint16_t(int16_t(-2000))), -1024.0);
  EXPECT_EQ(hu(pad, uint16_t(int16_t(-1999))), -1999.0);
  const Volume range = importEveryWord(kFormats[5]);
  // Air (-1024 HU) is below what u16 with intercept 0 holds: padding becomes its lowest, 0.
  EXPECT_EQ(hu(range, 50), 0.0);
  EXPECT_EQ(hu(range, 100), 0.0);
  EXPECT_EQ(hu(range, 101), 101.0);
  const Volume range12 = importEveryWord(kFormats[6]);
  EXPECT_EQ(hu(range12, 0x0800), -1024.0);  // -2048 as 12 bits: padding, so air
  EXPECT_EQ(hu(range12, 0x0C18), -1024.0);  // -1000: the range's end, padding too
  EXPECT_EQ(hu(range12, 0x0C19), -999.0);
}

// Several broken files: the error is the one of the first broken file in the folder's order,
// whichever thread reached which file first (both paths report through PixelFile).
TEST(DicomNativeFrames, TheFirstBrokenFileIsTheOneReported) {
  test::TempDir dir;
  for (int k = 0; k < 8; ++k) {
    test::TestSlice s;
    s.size = 64;
    s.z = k;
    s.instance = k + 1;
    const std::string path = dir.file(std::to_string(k) + ".dcm");
    test::writeTestSlice(path, s);
    if (k == 3 || k == 6) test::setPixelDataLength(path, 64 * 64 * 2 - 64);  // one row short
  }
  for (int run = 0; run < 5; ++run) {
    const std::string m = test::importError(dir.path().string());
    EXPECT_NE(m.find("3.dcm: "), std::string::npos) << m;
    EXPECT_EQ(m.find("6.dcm"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace voxray
