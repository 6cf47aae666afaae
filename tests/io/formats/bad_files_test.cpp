// Damaged and hostile volume files: each gives a voxray::Error (Input) that names the file
// and says what is wrong, never a crash, a hang or a silently wrong volume.
#include <filesystem>

#include "format_test_support.h"
#include "nifti_writer.h"
#include "voxray/io/load.h"

namespace voxray {
namespace {

using test::TempDir;
using testing::HasSubstr;

std::string loadError(const std::string& path) {
  const std::string m = test::errorMessage([&] { loadVolume(path); });
  EXPECT_THAT(m, HasSubstr(path));
  return m;
}

void truncate(const std::string& path, size_t keep) {
  std::vector<uint8_t> bytes = test::readBytes(path);
  ASSERT_GT(bytes.size(), keep);
  bytes.resize(keep);
  test::writeBytes(path, bytes);
}

test::NiftiSpec bigSpec() {
  test::NiftiSpec s;
  s.dims = {64, 64, 16};
  s.sformCode = 1;
  return s;
}

TEST(FormatsBadFiles, TruncatedGzip) {
  TempDir dir;
  test::writeNifti(dir.file("t.nii.gz"), bigSpec());
  truncate(dir.file("t.nii.gz"), test::readBytes(dir.file("t.nii.gz")).size() / 2);
  EXPECT_THAT(loadError(dir.file("t.nii.gz")), HasSubstr("shorter than the header says"));
}

TEST(FormatsBadFiles, NiftiDataShorterThanTheHeader) {
  TempDir dir;
  test::writeNifti(dir.file("t.nii"), bigSpec());
  truncate(dir.file("t.nii"), 352 + 1000);
  EXPECT_THAT(loadError(dir.file("t.nii")), HasSubstr("shorter than the header says"));
}

TEST(FormatsBadFiles, NrrdDataShorterThanTheHeader) {
  TempDir dir;
  const std::string header =
      "NRRD0004\ntype: short\ndimension: 3\nsizes: 64 64 16\nendian: little\nencoding: raw\n\n";
  std::vector<uint8_t> bytes(header.begin(), header.end());
  bytes.resize(bytes.size() + 1000);
  test::writeBytes(dir.file("t.nrrd"), bytes);
  EXPECT_THAT(loadError(dir.file("t.nrrd")), HasSubstr("cannot be read"));
}

TEST(FormatsBadFiles, MetaImageDataFileMissing) {
  TempDir dir;
  const std::string header =
      "ObjectType = Image\nNDims = 3\nDimSize = 4 3 2\nElementType = MET_SHORT\n"
      "ElementDataFile = gone.raw\n";
  test::writeBytes(dir.file("t.mhd"), std::vector<uint8_t>(header.begin(), header.end()));
  EXPECT_THAT(loadError(dir.file("t.mhd")), HasSubstr("cannot be read"));
}

TEST(FormatsBadFiles, NanSpacing) {
  TempDir dir;
  test::NiftiSpec s;
  s.sformCode = 1;
  s.sform[1][1] = std::nan("");
  test::writeNifti(dir.file("n.nii"), s);
  EXPECT_THAT(loadError(dir.file("n.nii")), HasSubstr("not a number"));
  const std::string nrrd =
      "NRRD0004\ntype: short\ndimension: 3\nspace: left-posterior-superior\nsizes: 4 3 2\n"
      "space directions: (nan,0,0) (0,1,0) (0,0,1)\nendian: little\nencoding: raw\n\n";
  std::vector<uint8_t> bytes(nrrd.begin(), nrrd.end());
  bytes.resize(bytes.size() + 48);
  test::writeBytes(dir.file("n.nrrd"), bytes);
  loadError(dir.file("n.nrrd"));  // ITK refuses it, or the geometry check does
}

TEST(FormatsBadFiles, ZeroDirectionMatrix) {
  TempDir dir;
  test::NiftiSpec s;
  s.sformCode = 1;
  for (auto& row : s.sform)
    for (double& x : row) x = 0;
  test::writeNifti(dir.file("z.nii"), s);
  EXPECT_THAT(loadError(dir.file("z.nii")), HasSubstr("zero direction or spacing"));
  const std::string mha =
      "ObjectType = Image\nNDims = 3\nBinaryData = True\nTransformMatrix = 0 0 0 0 0 0 0 0 0\n"
      "DimSize = 4 3 2\nElementType = MET_SHORT\nElementDataFile = LOCAL\n";
  std::vector<uint8_t> bytes(mha.begin(), mha.end());
  bytes.resize(bytes.size() + 48);
  test::writeBytes(dir.file("z.mha"), bytes);
  EXPECT_THAT(loadError(dir.file("z.mha")), HasSubstr("zero direction or spacing"));
}

TEST(FormatsBadFiles, DimsOverflowingSizeT) {
  TempDir dir;
  const std::string nrrd =
      "NRRD0004\ntype: short\ndimension: 3\nsizes: 4294967296 4294967296 4294967296\n"
      "endian: little\nencoding: raw\n\n";
  test::writeBytes(dir.file("o.nrrd"), std::vector<uint8_t>(nrrd.begin(), nrrd.end()));
  loadError(dir.file("o.nrrd"));
  // NIfTI-1 dims are int16: 32767^3 voxels is more than Voxray holds.
  test::writeNifti(dir.file("o.nii"), test::NiftiSpec{});
  std::vector<uint8_t> bytes = test::readBytes(dir.file("o.nii"));
  for (size_t at : {42u, 44u, 46u}) bytes[at] = 0xff, bytes[at + 1] = 0x7f;
  test::writeBytes(dir.file("o.nii"), bytes);
  EXPECT_THAT(loadError(dir.file("o.nii")), HasSubstr("more voxels than Voxray can hold"));
}

TEST(FormatsBadFiles, EmptyFileAndFolder) {
  TempDir dir;
  test::writeBytes(dir.file("e.nii.gz"), {});
  EXPECT_THAT(loadError(dir.file("e.nii.gz")), HasSubstr("empty"));
  std::filesystem::create_directory(dir.file("x.nii"));
  EXPECT_THAT(loadError(dir.file("x.nii")), HasSubstr("is a folder"));
}

TEST(FormatsBadFiles, NotNiftiAtAll) {
  TempDir dir;
  test::writeBytes(dir.file("junk.nii"), std::vector<uint8_t>(400, 'x'));
  EXPECT_THAT(loadError(dir.file("junk.nii")), HasSubstr("not a readable NIfTI file"));
  test::writeBytes(dir.file("junk.nrrd"), std::vector<uint8_t>(400, 'x'));
  EXPECT_THAT(loadError(dir.file("junk.nrrd")), HasSubstr("not a readable NRRD file"));
}

}  // namespace
}  // namespace voxray
