// Damaged and hostile volume files: each gives a voxray::Error (Input) that names the file
// and says what is wrong, never a crash, a hang or a silently wrong volume.
#include <cmath>
#include <filesystem>
#include <utility>

#include "format_test_support.h"
#include "nifti_writer.h"
#include "voxray/io/load.h"

namespace voxray {
namespace {

using test::TempDir;
using testing::HasSubstr;

using test::loadError;

// Writes a hand-made header (then DATA_BYTES zero bytes) as NAME; returns loadVolume's error.
std::string headerError(const std::string& name, const std::string& header, size_t dataBytes = 0) {
  TempDir dir;
  test::writeHeaderFile(dir.file(name), header, std::vector<uint8_t>(dataBytes));
  return loadError(dir.file(name));
}

// Writes SPEC with the NIfTI library's writer; returns loadVolume's error.
std::string niftiError(const test::NiftiSpec& spec) {
  TempDir dir;
  test::writeNifti(dir.file("bad.nii"), spec);
  return loadError(dir.file("bad.nii"));
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
  EXPECT_THAT(headerError("t.nrrd",
                          "NRRD0004\ntype: short\ndimension: 3\nsizes: 64 64 16\nendian: "
                          "little\nencoding: raw\n\n",
                          1000),
              HasSubstr("the data cannot be read"));
}

TEST(FormatsBadFiles, MetaImageDataFileMissing) {
  EXPECT_THAT(headerError("t.mhd",
                          "ObjectType = Image\nNDims = 3\nDimSize = 4 3 2\n"
                          "ElementType = MET_SHORT\nElementDataFile = gone.raw\n"),
              HasSubstr("its data file 'gone.raw' is missing"));
}

TEST(FormatsBadFiles, NanSpacing) {
  test::NiftiSpec s;
  s.sformCode = 1;
  s.sform[1][1] = std::nan("");
  EXPECT_THAT(niftiError(s), HasSubstr("not a number"));
  EXPECT_THAT(headerError("n.nrrd",
                          "NRRD0004\ntype: short\ndimension: 3\nspace: left-posterior-superior\n"
                          "sizes: 4 3 2\nspace directions: (nan,0,0) (0,1,0) (0,0,1)\n"
                          "endian: little\nencoding: raw\n\n",
                          48),
              HasSubstr("not a readable NRRD file"));  // Teem: "existance of ... coefficients"
}

TEST(FormatsBadFiles, ZeroDirectionMatrix) {
  test::NiftiSpec s;
  s.sformCode = 1;
  for (auto& row : s.sform)
    for (double& x : row) x = 0;
  EXPECT_THAT(niftiError(s), HasSubstr("zero direction or spacing"));
  EXPECT_THAT(headerError("z.mha",
                          "ObjectType = Image\nNDims = 3\nBinaryData = True\n"
                          "TransformMatrix = 0 0 0 0 0 0 0 0 0\nDimSize = 4 3 2\n"
                          "ElementType = MET_SHORT\nElementDataFile = LOCAL\n",
                          48),
              HasSubstr("zero direction or spacing"));
}

// A MetaImage header is text, one word-named field per line, each field once: anything else
// is refused before MetaIO reads it (it reads on into such damage; libFuzzer found heap
// corruption behind one).
TEST(FormatsBadFiles, MetaImageHeaderThatIsNotTextFieldsIsRefused) {
  const std::string tail = "DimSize = 4 3 2\nElementType = MET_SHORT\nElementDataFile = LOCAL\n";
  EXPECT_THAT(headerError("b.mha",
                          "ObjectType = Image\nNDims = 3\nComment = a\x04"
                          "b\n" +
                              tail,
                          48),
              HasSubstr("header line 3 holds the byte 0x04, which is not text"));
  EXPECT_THAT(headerError("w.mha", "ObjectType = Image\nNDims = 3\nDim Size = 4 3 2\n" + tail, 48),
              HasSubstr("header line 3 is not a 'Name = value' field"));
  EXPECT_THAT(headerError("d.mha", "ObjectType = Image\nNDims = 3\nNDims = 3\n" + tail, 48),
              HasSubstr("header line 3 gives the field NDims a second time"));
  // The same header without the damage opens.
  TempDir dir;
  const std::string good = dir.file("g.mha");
  test::writeHeaderFile(good, "ObjectType = Image\nNDims = 3\nComment = a b\n" + tail,
                        std::vector<uint8_t>(48));
  const Volume v = loadVolume(good);
  EXPECT_EQ(v.dims, glm::ivec3(4, 3, 2));
}

// A file list's dimension: "LIST" in a 2D image would list 1D files, which is refused.
TEST(FormatsBadFiles, MetaImageListOfLinesIsRefused) {
  EXPECT_THAT(headerError("l.mhd",
                          "ObjectType = Image\nNDims = 2\nDimSize = 4 3\n"
                          "ElementType = MET_SHORT\nElementDataFile = LIST\nslice.raw\n"),
              HasSubstr("its files hold 1D images of a 2D image"));
  EXPECT_THAT(headerError("m.mhd",
                          "ObjectType = Image\nNDims = 3\nDimSize = 4 3 2\n"
                          "ElementType = MET_SHORT\nElementDataFile = LIST 4D\nslice.raw\n"),
              HasSubstr("its files hold 4D images of a 3D image"));
}

// The list forms that are read: LIST 2D, and LIST alone in a 3D image (2D files too).
TEST(FormatsBadFiles, MetaImageListsOfSlicesOpen) {
  for (const char* list : {"LIST 2D", "LIST"}) {
    SCOPED_TRACE(list);
    TempDir dir;
    for (int k = 0; k < 2; ++k) {
      std::vector<int16_t> slice(12);
      for (int i = 0; i < 12; ++i) slice[size_t(i)] = int16_t(100 * k + i);
      std::ofstream out(dir.file("s" + std::to_string(k) + ".raw"), std::ios::binary);
      out.write(reinterpret_cast<const char*>(slice.data()), 24);
    }
    test::writeHeaderFile(dir.file("v.mhd"),
                          "ObjectType = Image\nNDims = 3\nDimSize = 4 3 2\n"
                          "ElementType = MET_SHORT\nElementDataFile = " +
                              std::string(list) + "\ns0.raw\ns1.raw\n",
                          {});
    const Volume v = loadVolume(dir.file("v.mhd"));
    ASSERT_EQ(v.dims, glm::ivec3(4, 3, 2));
    EXPECT_EQ(v.toPhysical(v.at(3, 2, 0)), 11.0);
    EXPECT_EQ(v.toPhysical(v.at(1, 0, 1)), 101.0);
  }
}

TEST(FormatsBadFiles, DimsOverflowingSizeT) {
  TempDir dir;
  EXPECT_THAT(headerError("o.nrrd",
                          "NRRD0004\ntype: short\ndimension: 3\nsizes: 4294967296 "
                          "4294967296 4294967296\nendian: little\nencoding: raw\n\n"),
              HasSubstr("too large"));  // Teem: "too large to be represented in type size_t"
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

// The inputs voxray_volume_file_fuzzer broke the readers with (tests/fuzz/regressions/README.md):
// each now ends in the message for what is wrong, not a crash, a leak or NaN voxels.
TEST(FormatsBadFiles, FuzzerRegressionsEndInTheirMessages) {
  const std::filesystem::path dir = VOXRAY_FUZZ_REGRESSIONS;
  const std::pair<const char*, const char*> cases[] = {
      {"nifti2-swapped-header-stack-overrun.nii", "not a readable NIfTI file (dim[0] is"},
      {"nifti2-claims-13gb.nii", "shorter than the header says (it claims 13153337408 bytes"},
      {"nrrd-bad-magic-teem-leak.nrrd", "does not start with a NRRD0001"},
      {"mhd-pattern-metaio-leak.mha", "is not a slice pattern Voxray reads"},
      {"mha-long-header-line-metaio-overflow.mhd", "header line 8 is 281 characters long"},
      {"mha-huge-ndims-metaio-hang.mha", "Voxray opens 2 to 10 dimensions"},
      {"mha-ndims-1-metaio-heap-corruption.mha", "header line 2 holds the byte 0x97"},
      {"mha-line-without-separator-metaio-overflow.mha",
       "header line 3 is not a 'Name = value' field"},
      {"mha-datafile-in-a-value-metaio-overflow.mha", "header line 4 is 304 characters long"},
      {"mhd-list-word-metaio-segv.mhd", "is not a file list Voxray reads (LIST, or LIST 2D)"}};
  for (const auto& [name, message] : cases)
    EXPECT_THAT(loadError((dir / name).string()), HasSubstr(message)) << name;
  // Denormal scaling: the volume loads, with finite voxels and a usable storage scale.
  for (const char* name : {"nifti2-denormal-slope.nii", "nifti2-tiny-span.nii"}) {
    const Volume v = loadVolume((dir / name).string());
    EXPECT_EQ(v.voxels.size(), v.voxelCount()) << name;
    EXPECT_TRUE(std::isfinite(1.0 / v.slope) && v.slope > 0.0) << name;
  }
}

}  // namespace
}  // namespace voxray
