// Input that once crashed or aborted Voxray (issue 19): text in the dataset's own character
// set, sequences nested 100,000 deep, headers claiming more frames than the file holds.
// Each input is made here; none is kept as a blob.
#include <gmock/gmock.h>

#include <filesystem>

#include "../io/test_support.h"
#include "dicom_writer.h"
#include "test_data.h"

namespace voxray {
namespace {

using ::testing::HasSubstr;

// The listing of one slice written with TEXT (charset, description, name).
SeriesInfo listOne(const test::TestSlice& text) {
  test::TempDir dir;
  test::writeTestSlice(dir.file("1.dcm"), text);
  DicomListing l = listDicomSeries(dir.file("1.dcm"));
  EXPECT_EQ(l.series.size(), 1u);
  return l.series.empty() ? SeriesInfo{} : l.series[0];
}

TEST(DicomText, Latin1IsDecodedToUtf8) {
  test::TestSlice s;
  s.charset = "ISO_IR 100";
  s.description =
      "Kn\xF6"
      "chel Sch\xE4"
      "del";
  s.patientName =
      "M\xFC"
      "ller^J\xFC"
      "rgen";
  SeriesInfo info = listOne(s);
  EXPECT_EQ(info.description, "Knöchel Schädel");
  EXPECT_EQ(info.patientName, "Müller^Jürgen");
}

TEST(DicomText, Utf8IsKept) {
  test::TestSlice s;
  s.charset = "ISO_IR 192";
  s.description = "Thorax – Übersicht";
  s.patientName = "Dvořák^Antonín";
  SeriesInfo info = listOne(s);
  EXPECT_EQ(info.description, "Thorax – Übersicht");
  EXPECT_EQ(info.patientName, "Dvořák^Antonín");
}

TEST(DicomText, Gb18030IsDecoded) {
  test::TestSlice s;
  s.charset = "GB18030";
  s.description = "\xD0\xD8\xB2\xBF CT";                      // 胸部 CT
  s.patientName = "Wang^XiaoDong=\xCD\xF5^\xD0\xA1\xB6\xAB";  // PS3.5 J.3: 王^小东
  SeriesInfo info = listOne(s);
  EXPECT_EQ(info.description, "胸部 CT");
  EXPECT_EQ(info.patientName, "Wang^XiaoDong=王^小东");
}

TEST(DicomText, Iso2022JapaneseIsDecoded) {
  // PS3.5 H.3.1: the name in romaji, kanji and hiragana, JIS X 0208 behind escape sequences.
  test::TestSlice s;
  s.charset = "\\ISO 2022 IR 87";
  s.patientName =
      "Yamada^Tarou=\x1b$B;3ED\x1b(B^\x1b$BB@O:\x1b(B=\x1b$B$d$^$@\x1b(B^\x1b$B$?$m$&\x1b(B";
  s.description = "\x1b$B;3ED\x1b(B";
  SeriesInfo info = listOne(s);
  EXPECT_EQ(info.patientName, "Yamada^Tarou=山田^太郎=やまだ^たろう");
  EXPECT_EQ(info.description, "山田");
}

TEST(DicomText, BytesThatDoNotDecodeAreReplaced) {
  test::TestSlice s;
  s.charset = "ISO_IR 192";
  s.description = "Kopf \xC3( \xFF";  // a broken two-byte sequence and a byte UTF-8 never uses
  EXPECT_EQ(listOne(s).description, "Kopf \xEF\xBF\xBD( \xEF\xBF\xBD");
  test::TestSlice undeclared;
  undeclared.description =
      "Kn\xF6"
      "chel";  // Latin-1 without SpecificCharacterSet
  EXPECT_EQ(listOne(undeclared).description,
            "Kn\xEF\xBF\xBD"
            "chel");
}

TEST(DicomText, AFlippedByteInModalityIsReplacedNotFatal) {
  test::TestSlice s;
  s.modality = "C\xD4";
  SeriesInfo info = listOne(s);
  EXPECT_EQ(info.modality, "C\xEF\xBF\xBD");
}

TEST(DicomHostile, SequencesNestedTooDeepAreRefused) {
  // 257 and 1,000 fit the parser's stack budget (about 1,400 levels) and are counted.
  for (int depth : {257, 1000, 10000, 100000}) {
    test::TempDir dir;
    const std::string path = dir.file("nested.dcm");
    test::writeTestSlice(path, {});
    test::nestSequences(path, depth);
    std::string m;
    try {
      listDicomSeries(path);
    } catch (const Error& e) {
      m = e.what();
    }
    EXPECT_THAT(m, HasSubstr("nested deeper than Voxray reads (over 256 levels)")) << depth;
    EXPECT_THAT(test::importError(path), HasSubstr("nested deeper than Voxray reads")) << depth;
  }
}

TEST(DicomHostile, GreyscaleWithThreeSamplesIsInconsistentNotColour) {
  test::TempDir dir;
  test::TestSlice s;
  s.photometric = "MONOCHROME1";
  s.samplesPerPixel = 3;
  test::writeTestSlice(dir.file("1.dcm"), s);
  const std::string m = test::importError(dir.file("1.dcm"));
  EXPECT_THAT(m, HasSubstr("says MONOCHROME1 (greyscale) but has 3 samples per pixel"));
  EXPECT_THAT(m, testing::Not(HasSubstr("colour")));
}

TEST(DicomHostile, NestingUpToTheLimitLoads) {
  test::TempDir dir;
  const std::string path = dir.file("nested.dcm");
  test::writeTestSlice(path, {});
  test::nestSequences(path, 256);  // kMaxNestingDepth
  Volume v = importDicom(path);
  EXPECT_EQ(v.dims, glm::ivec3(4, 4, 1));
  EXPECT_EQ(v.toPhysical(v.voxels[0]), -8.0);
  EXPECT_EQ(v.toPhysical(v.voxels[15]), 7.0);
}

TEST(DicomHostile, FramesTheFileCannotHoldAreRefusedBeforeAllocating) {
  test::TempDir dir;
  const std::string path = dir.file("frames.dcm");
  test::TestSlice s;
  s.size = 512;
  s.numberOfFrames = 2000;  // 1 GB of frames claimed, one frame (512 KB) stored
  test::writeTestSlice(path, s);
  const std::string m = test::importError(path);
  EXPECT_THAT(m.substr(0, 400),
              HasSubstr("the header describes 2000 frame(s) of 512x512 pixels (1048576000 "
                        "bytes) but the file holds only"));
}

TEST(DicomHostile, ElementLongerThanTheFileIsRefusedBeforeAllocating) {
  // PixelData claiming 4 GiB in a file of a few hundred bytes: DCMTK checks the length
  // against what the file holds before it allocates (ASan would report a 4 GiB allocation).
  test::TempDir dir;
  const std::string path = dir.file("long.dcm");
  test::writeTestSlice(path, {});
  test::setPixelDataLength(path, 0xFFFFFFF0u);
  EXPECT_THAT(test::importError(path), HasSubstr("long.dcm: cannot be read ("));
}

TEST(DicomHostile, ParserExceptionOnAMutatedDicomdirIsAnError) {
  // DCMTK throws std::out_of_range from basic_string::erase on this file; it once aborted
  // voxray-cli. The message names the file and what went wrong.
  const std::string path =
      std::string(VOXRAY_FUZZ_REGRESSIONS) + "/dicomdir-erase-out-of-range.dcm";
  std::string m;
  try {
    listDicomSeries(path);
  } catch (const Error& e) {
    m = e.what();
  }
  EXPECT_THAT(m, HasSubstr("dicomdir-erase-out-of-range.dcm: no DICOM image found"));
  EXPECT_THAT(m, HasSubstr("damaged DICOM (the DICOM parser failed (basic_string::erase"));
}

TEST(DicomHostile, EveryFuzzerRegressionIsAVolumeOrAnError) {
  int inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(VOXRAY_FUZZ_REGRESSIONS)) {
    if (entry.path().extension() == ".md") continue;
    ++inputs;
    for (bool listOnly : {true, false}) {
      try {
        if (listOnly)
          listDicomSeries(entry.path().string());
        else
          importDicom(entry.path().string());
      } catch (const Error&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << entry.path() << ": " << e.what();
      }
    }
  }
  EXPECT_GE(inputs, 1);
}

}  // namespace
}  // namespace voxray
