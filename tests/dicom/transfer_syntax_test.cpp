// Every transfer syntax decodes to identical pixels; broken data fails cleanly.
#include "test_data.h"

namespace voxray {
namespace {

using test::dicomPath;

void expectSamePixels(const std::string& reference, const std::string& other) {
  Volume a = importDicom(dicomPath(reference));
  Volume b = importDicom(dicomPath(other));
  ASSERT_EQ(a.dims, b.dims) << other;
  size_t differ = 0;
  for (size_t i = 0; i < a.voxels.size(); ++i)
    differ += a.toPhysical(a.voxels[i]) != b.toPhysical(b.voxels[i]);
  EXPECT_EQ(differ, 0u) << other;
  EXPECT_EQ(a.originMm, b.originMm) << other;
}

class TransferSyntaxes : public testing::TestWithParam<int> {};

TEST_P(TransferSyntaxes, DecodesToTheSamePixelsAsExplicitLittleEndian) {
  expectSamePixels("transfer-syntaxes/1.dcm",
                   "transfer-syntaxes/" + std::to_string(GetParam()) + ".dcm");
}
// 2 implicit LE, 3 big endian, 4 RLE, 5-6 JPEG lossless, 7-8 JPEG-LS, 9 JPEG 2000.
INSTANTIATE_TEST_SUITE_P(All, TransferSyntaxes, testing::Range(2, 10));

// A Siemens mosaic: its 35 slices of 64 x 64 cut from the 384 x 384 image (mosaic_test.cpp
// checks them against dcm2niix).
TEST(DicomTransferSyntax, ReferenceSliceHasTheExpectedValues) {
  Volume v = importDicom(dicomPath("transfer-syntaxes/1.dcm"));
  EXPECT_EQ(v.dims, glm::ivec3(64, 64, 35));
  EXPECT_DOUBLE_EQ(test::physicalMax(v), 2362.0);
  EXPECT_DOUBLE_EQ(test::physicalMin(v), 0.0);
}

TEST(DicomTransferSyntax, EnhancedMrCodecsAgree) {
  for (const char* f : {"emri_small_RLE.dcm", "emri_small_big_endian.dcm",
                        "emri_small_jpeg_2k_lossless.dcm", "emri_small_jpeg_ls_lossless.dcm"})
    expectSamePixels("pydicom-data/emri_small.dcm", std::string("pydicom-data/") + f);
}

TEST(DicomTransferSyntax, CtJpeg2000MatchesUncompressed) {
  expectSamePixels("pydicom-data/693_UNCR.dcm", "pydicom-data/693_J2KR.dcm");
  Volume v = importDicom(dicomPath("pydicom-data/693_J2KR.dcm"));
  EXPECT_DOUBLE_EQ(test::physicalMin(v), -1024.0);
  EXPECT_DOUBLE_EQ(test::physicalMax(v), 1468.0);
}

TEST(DicomTransferSyntax, CompressedSeriesMatchUncompressed) {
  // The same series in J2K (twice), JPEG lossless, JPEG-LS and RLE.
  for (const char* d : {"compressed", "compressed_j2k", "compressed_jpeg", "compressed_jpegls"})
    expectSamePixels("edge-cases/generic/compressed_rle/001",
                     std::string("edge-cases/generic/") + d + "/001");
}

TEST(DicomTransferSyntax, TruncatedJpeg2000FailsCleanly) {
  std::string m =
      test::importError(dicomPath("pydicom-data/emri_small_jpeg_2k_lossless_too_short.dcm"));
  EXPECT_NE(m.find("emri_small_jpeg_2k_lossless_too_short.dcm"), std::string::npos) << m;
  EXPECT_NE(m.find("damaged or incomplete"), std::string::npos) << m;
}

TEST(DicomTransferSyntax, OddSequenceFileStillDecodes) {
  Volume v = importDicom(dicomPath("pydicom-data/bad_sequence.dcm"));
  EXPECT_EQ(v.dims, glm::ivec3(512, 512, 1));
  EXPECT_DOUBLE_EQ(test::physicalMin(v), -1011.0);
  EXPECT_DOUBLE_EQ(test::physicalMax(v), 1243.0);
}

}  // namespace
}  // namespace voxray
