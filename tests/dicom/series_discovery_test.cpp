// Series discovery, listing and the default choice (issue 3: ct-philips-phantom and
// folders without any volume).
#include <filesystem>
#include <fstream>
#include <random>

#include "test_data.h"

namespace voxray {
namespace {

using test::anyContains;
using test::dicomPath;

const SeriesInfo* findNumber(const DicomListing& l, int number) {
  for (auto& s : l.series)
    if (s.number == number) return &s;
  return nullptr;
}

TEST(DicomSeriesDiscovery, PhilipsPhantomChoosesThe28SliceVolume) {
  DicomListing l = listDicomSeries(dicomPath("ct-philips-phantom"));
  ASSERT_FALSE(l.series.empty());
  const SeriesInfo& chosen = l.series.front();
  EXPECT_TRUE(chosen.chosenByDefault);
  EXPECT_EQ(chosen.number, 201);
  EXPECT_EQ(chosen.sliceCount, 28);
  EXPECT_EQ(chosen.dims, glm::ivec3(512, 512, 28));
  EXPECT_NEAR(chosen.spacingMm.x, 0.451171875, 1e-9);
  EXPECT_NEAR(chosen.spacingMm.z, 5.0, 1e-6);
  EXPECT_EQ(chosen.modality, "CT");
  int chosenCount = 0;
  for (auto& s : l.series) chosenCount += s.chosenByDefault;
  EXPECT_EQ(chosenCount, 1);
  // Display fields are available to the UI ...
  EXPECT_EQ(chosen.patientName, "HEAD");
  EXPECT_EQ(chosen.patientId, "PLASTIC");
  // ... but never in notes.
  EXPECT_FALSE(anyContains(l.notes, "PLASTIC"));
}

// The loaded volume carries its study and series identity (for PACS send-back and the
// opt-in corner text); the identifying fields are the same as the listing's.
TEST(DicomSeriesDiscovery, VolumeCarriesItsStudyIdentity) {
  DicomListing l = listDicomSeries(dicomPath("ct-philips-phantom"));
  Volume v = importDicom(dicomPath("ct-philips-phantom"));
  const SeriesInfo& chosen = l.series.front();
  EXPECT_EQ(v.study.seriesInstanceUid, chosen.uid);
  EXPECT_EQ(v.study.seriesNumber, 201);
  EXPECT_EQ(v.study.patientName, "HEAD");
  EXPECT_EQ(v.study.patientId, "PLASTIC");
  // A UID is digits and dots, at least "1.2" and at most 64 characters (PS3.5 9.1).
  EXPECT_GE(v.study.studyInstanceUid.size(), 3u);
  EXPECT_LE(v.study.studyInstanceUid.size(), 64u);
  EXPECT_EQ(v.study.studyInstanceUid.find_first_not_of("0123456789."), std::string::npos);
  EXPECT_NE(v.study.studyInstanceUid, v.study.seriesInstanceUid);
  EXPECT_FALSE(anyContains(v.warnings, "PLASTIC"));
}

TEST(DicomSeriesDiscovery, PhilipsScoutAndSummaryPagesAreListedNotChosen) {
  DicomListing l = listDicomSeries(dicomPath("ct-philips-phantom"));
  const SeriesInfo* scout = findNumber(l, 100);
  ASSERT_NE(scout, nullptr);
  EXPECT_FALSE(scout->isVolume);
  EXPECT_FALSE(scout->chosenByDefault);
  EXPECT_NE(scout->notVolumeReason.find("localizer"), std::string::npos);
  const SeriesInfo* pages = findNumber(l, 401);
  ASSERT_NE(pages, nullptr);
  EXPECT_FALSE(pages->isVolume);
  EXPECT_NE(pages->notVolumeReason.find("secondary capture"), std::string::npos);
  // LICENSE and four DIRFILEs (DICOMDIRs) are skipped and counted, not fatal.
  EXPECT_EQ(l.filesSkipped, 5);
  EXPECT_TRUE(anyContains(l.notes, "not a DICOM file"));
}

TEST(DicomSeriesDiscovery, DicomDirWithStaleEntriesFallsBackToItsFolder) {
  Volume v = importDicom(dicomPath("ct-philips-phantom/DIRFILE"));
  EXPECT_EQ(v.dims, glm::ivec3(512, 512, 28));
  EXPECT_TRUE(anyContains(v.warnings, "DICOMDIR lists 5 file(s) that do not exist"));
}

TEST(DicomSeriesDiscovery, DefaultLoadIsTheVolumeInHounsfield) {
  Volume v = importDicom(dicomPath("ct-philips-phantom"));
  EXPECT_EQ(v.dims, glm::ivec3(512, 512, 28));
  EXPECT_NEAR(v.spacingMm.z, 5.0, 1e-6);
  EXPECT_EQ(v.unit, "HU");
  EXPECT_DOUBLE_EQ(v.intercept, -1024.0);
  EXPECT_DOUBLE_EQ(test::physicalMin(v), -1024.0);
  EXPECT_NEAR(v.originMm.z, 696.21, 1e-6);
  EXPECT_FALSE(anyContains(v.warnings, "PLASTIC"));
}

TEST(DicomSeriesDiscovery, SeriesSelectorLoadsAScoutOnRequest) {
  LoadOptions o;
  o.series = "100";
  Volume v = importDicom(dicomPath("ct-philips-phantom"), o);
  EXPECT_EQ(v.dims, glm::ivec3(512, 256, 1));
  EXPECT_TRUE(anyContains(v.warnings, "not a volume"));
}

TEST(DicomSeriesDiscovery, SelectorByUidMatchesNumber) {
  DicomListing l = listDicomSeries(dicomPath("ct-philips-phantom"));
  LoadOptions o;
  o.series = l.series.front().uid;
  EXPECT_EQ(importDicom(dicomPath("ct-philips-phantom"), o).dims.z, 28);
}

TEST(DicomSeriesDiscovery, UnknownSelectorListsTheCandidates) {
  std::string m = test::importError(dicomPath("ct-philips-phantom"), "999");
  EXPECT_NE(m.find("no series \"999\""), std::string::npos) << m;
  EXPECT_NE(m.find("201: 28 image(s) CT"), std::string::npos) << m;
  EXPECT_EQ(m.find("PLASTIC"), std::string::npos);
}

// Nine copies of one Siemens mosaic (a series each, one per transfer syntax): each is split
// into its 35 slices of 64 x 64 (6 x 6 tiles of the 384 x 384 image) and listed as a volume.
TEST(DicomSeriesDiscovery, FolderOfSingleMosaicsListsEachAsAVolume) {
  DicomListing l = listDicomSeries(dicomPath("transfer-syntaxes"));
  ASSERT_EQ(l.series.size(), 9u);
  for (const SeriesInfo& s : l.series) {
    EXPECT_TRUE(s.isVolume) << s.selector << ": " << s.notVolumeReason;
    EXPECT_EQ(s.dims, glm::ivec3(64, 64, 35)) << s.selector;
    EXPECT_EQ(s.sliceCount, 35) << s.selector;
    EXPECT_EQ(s.fileCount, 1) << s.selector;
  }
  EXPECT_TRUE(l.series.front().chosenByDefault);
}

TEST(DicomSeriesDiscovery, PrivacyPatientFieldsNeverInMessages) {
  Volume v = importDicom(dicomPath("ct-visible-human-pelvis"));
  EXPECT_FALSE(anyContains(v.warnings, "Eve"));
  std::string m = test::importError(dicomPath("ct-visible-human-pelvis"), "7");
  EXPECT_EQ(m.find("Eve"), std::string::npos) << m;
  EXPECT_EQ(m.find("000-000-001"), std::string::npos) << m;
}

TEST(DicomSeriesDiscovery, MissingPathSaysSo) {
  std::string m = test::importError(dicomPath("does-not-exist"));
  EXPECT_NE(m.find("no such file or folder"), std::string::npos) << m;
}

TEST(DicomSeriesDiscovery, NonDicomFileIsRefusedNotCrashed) {
  std::string m = test::importError(dicomPath("ct-ge-tilt/LICENSE"));
  EXPECT_NE(m.find("no DICOM image found"), std::string::npos) << m;
}

// Issue 41 item 8: "401 file(s) skipped: not a DICOM file" for the .tif files of a mixed
// folder; the note says what they are and how to open them.
class MixedFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("voxray-mixed-" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(dir_);
    for (int k = 1; k <= 3; ++k) write("slice" + std::to_string(k) + ".tif", {'I', 'I', '*', 0});
    write("big-endian.tif", {'M', 'M', 0, '*'});
    write("photo.png", {char(0x89), 'P', 'N', 'G'});
    write("notes.txt", {'h', 'i'});
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void write(const std::string& name, std::vector<char> bytes) {
    bytes.resize(200, 0);  // past a DICOM preamble, so no reader stops at the length
    std::ofstream(dir_ / name, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  }
  std::filesystem::path dir_;
};

TEST_F(MixedFolder, SkippedFilesSayWhatTheyAre) {
  // Alone: the refusal says what the folder holds.
  const std::string m = test::importError(dir_.string());
  EXPECT_NE(m.find("no DICOM image found in 6 file(s) (1 PNG image (not DICOM): "),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("; 4 TIFF images (not DICOM): if uncompressed, open the folder as a raw slice "
                   "stack (File > Open raw volume"),
            std::string::npos)
      << m;
  // Beside a DICOM series: listed, and each kind counted with what to do.
  for (const char* slice : {"01.dcm", "02.dcm"})
    std::filesystem::copy_file(dicomPath(std::string("ct-ge-tilt/") + slice), dir_ / slice);
  const DicomListing l = listDicomSeries(dir_.string());
  EXPECT_EQ(l.filesSkipped, 6);
  EXPECT_TRUE(anyContains(l.notes,
                          "4 TIFF images (not DICOM): if uncompressed, open the folder "
                          "as a raw slice stack (File > Open raw volume"));
  EXPECT_TRUE(anyContains(l.notes, "1 PNG image (not DICOM): convert the stack to NIfTI"));
  EXPECT_TRUE(anyContains(l.notes, "1 file(s) skipped: not a DICOM file"));  // the text file
}

}  // namespace
}  // namespace voxray
