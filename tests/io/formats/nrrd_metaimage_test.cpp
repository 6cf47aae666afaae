// NRRD and MetaImage: shared DICOM series written by Teem's and MetaIO's own writers (with an axis
// reversed, so the file's grid differs from the DICOM's) open as the same volume in space;
// small headers written here check NRRD spaces other than LPS and MetaImage's TransformMatrix.
#include <cmath>

#include "format_test_support.h"
#include "volume_writer.h"
#include "voxray/io/dicom_import.h"
#include "voxray/io/load.h"

namespace voxray {
namespace {

using test::dicomData;
using test::TempDir;

const char* const kOblique = "edge-cases/siemens_multiframe/anatomical/001";
const char* const kSagittal = "edge-cases/philips_enhanced/anatomical/001";

void expectRoundTrip(const std::string& series, const std::string& name, int flipAxis,
                     bool compress) {
  SCOPED_TRACE(series + " as " + name);
  TempDir dir;
  const Volume truth = importDicom(dicomData(series));
  test::writeVolumeFile(truth, dir.file(name), flipAxis, compress);
  const Volume got = loadVolume(dir.file(name));
  // int16 written, int16 read: exact. Physical values written as float32 (a volume with a
  // non-integral rescale) come back within float32 rounding plus half a storage step.
  const bool asIs = truth.slope == 1.0 && truth.intercept == 0.0;
  const double tolerance = asIs ? 0.0 : got.slope / 2 + std::abs(test::physicalMax(truth)) * 1e-7;
  test::expectSameInSpace(truth, got, tolerance);
}

TEST(FormatsNrrd, ObliqueGzipInline) { expectRoundTrip(kOblique, "o.nrrd", 0, true); }
TEST(FormatsNrrd, SagittalDetachedRaw) { expectRoundTrip(kSagittal, "s.nhdr", 2, false); }
TEST(FormatsNrrd, SagittalDetachedGzip) { expectRoundTrip(kSagittal, "s.nhdr", 1, true); }
TEST(FormatsNrrd, AxialCtPelvis) { expectRoundTrip("ct-visible-human-pelvis", "p.nrrd", 0, false); }
TEST(FormatsMetaImage, ObliqueMha) { expectRoundTrip(kOblique, "o.mha", 2, false); }
TEST(FormatsMetaImage, SagittalMhdRaw) { expectRoundTrip(kSagittal, "s.mhd", 0, false); }
TEST(FormatsMetaImage, ObliqueMhdZraw) { expectRoundTrip(kOblique, "o.mhd", 1, true); }

// A 4x3x2 int16 volume holding its voxel index, after a text header.
void writeWithHeader(const std::string& path, const std::string& header) {
  std::vector<uint8_t> data;
  for (int16_t i = 0; i < 24; ++i) {
    data.push_back(uint8_t(i & 0xff));
    data.push_back(uint8_t(uint16_t(i) >> 8));
  }
  test::writeHeaderFile(path, header, data);
}

std::string nrrdHeader(const std::string& space) {
  return "NRRD0004\ntype: short\ndimension: 3\nspace: " + space +
         "\nsizes: 4 3 2\nspace directions: (2,0,0) (0,3,0) (0,0,4)\nkinds: domain domain "
         "domain\nendian: little\nencoding: raw\nspace origin: (10,20,30)\n\n";
}

TEST(FormatsNrrd, EverySpaceBecomesLps) {
  struct Case {
    const char* space;
    glm::dvec3 sign;  // LPS = sign * the file's coordinates
  };
  for (const Case& c :
       {Case{"right-anterior-superior", {-1, -1, 1}}, Case{"left-anterior-superior", {1, -1, 1}},
        Case{"left-posterior-superior", {1, 1, 1}}}) {
    SCOPED_TRACE(c.space);
    TempDir dir;
    writeWithHeader(dir.file("v.nrrd"), nrrdHeader(c.space));
    const Volume v = loadVolume(dir.file("v.nrrd"));
    EXPECT_EQ(v.dims, glm::ivec3(4, 3, 2));
    EXPECT_EQ(v.spacingMm, glm::dvec3(2, 3, 4));
    EXPECT_EQ(v.originMm, c.sign * glm::dvec3(10, 20, 30));
    for (int a = 0; a < 3; ++a) EXPECT_EQ(v.direction[a][a], c.sign[a]);
    EXPECT_EQ(v.at(3, 2, 1), 23);
  }
}

TEST(FormatsMetaImage, TransformMatrixRowsAreTheAxes) {
  TempDir dir;
  writeWithHeader(dir.file("v.mha"),
                  "ObjectType = Image\nNDims = 3\nBinaryData = True\n"
                  "BinaryDataByteOrderMSB = False\nCompressedData = False\n"
                  "TransformMatrix = 0 1 0 -1 0 0 0 0 1\nOffset = 1 2 3\n"
                  "ElementSpacing = 0.5 0.25 2\nDimSize = 4 3 2\nElementType = MET_SHORT\n"
                  "ElementDataFile = LOCAL\n");
  const Volume v = loadVolume(dir.file("v.mha"));
  EXPECT_EQ(v.dims, glm::ivec3(4, 3, 2));
  EXPECT_EQ(v.spacingMm, glm::dvec3(0.5, 0.25, 2));
  EXPECT_EQ(v.originMm, glm::dvec3(1, 2, 3));
  EXPECT_EQ(v.direction[0], glm::dvec3(0, 1, 0));   // i toward posterior
  EXPECT_EQ(v.direction[1], glm::dvec3(-1, 0, 0));  // j toward the patient's right
  EXPECT_EQ(v.at(1, 2, 1), 21);
}

}  // namespace
}  // namespace voxray
