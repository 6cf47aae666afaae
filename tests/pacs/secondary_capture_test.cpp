// Screenshots sent back: a Multi-frame True Color SC in the source's study, readable by
// dcmdump, found by a new C-FIND (or QIDO) after C-STORE (or STOW-RS), pixels unchanged.

#include <cstdio>
#include <filesystem>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <gmock/gmock.h>

#include "command_run.h"
#include "pacs_test_support.h"
#include "voxray/io/secondary_capture.h"

namespace voxray::test {
namespace {

using testing::HasSubstr;

// Two 64x48 frames of a pattern no codec or colour conversion would leave as it is.
std::vector<Image> frames() {
  std::vector<Image> out(2, Image(64, 48));
  for (int f = 0; f < 2; ++f)
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 64; ++x) {
        uint8_t* p = out[f].pixel(x, y);
        p[0] = uint8_t(x * 4), p[1] = uint8_t(y * 5), p[2] = uint8_t(f * 200 + (x ^ y)), p[3] = 255;
      }
  return out;
}

std::vector<uint8_t> rgbOf(const std::vector<Image>& images) {
  std::vector<uint8_t> rgb;
  for (const auto& im : images)
    for (size_t i = 0; i < im.rgba.size(); i += 4)
      rgb.insert(rgb.end(), &im.rgba[i], &im.rgba[i + 3]);
  return rgb;
}

std::string writeShot(const std::string& folder) {
  SecondaryCaptureInfo info;
  info.study = loadVolume(dicomPath("ct-philips-phantom/S2010")).study;
  std::string path = folder + "/shot.dcm";
  writeSecondaryCapture(path, frames(), info);
  return path;
}

TEST(SecondaryCaptureTest, DcmdumpReadsItAsAMultiframeTrueColorScInTheSourceStudy) {
  std::string path = writeShot(tempFolder("sc"));
  const CommandResult dumped = runCommand("dcmdump " + path + " 2>&1");
  const std::string& dump = dumped.output;
  ASSERT_EQ(dumped.exitCode, 0) << dump;
  EXPECT_THAT(dump, HasSubstr("=MultiframeTrueColorSecondaryCaptureImageStorage"));
  EXPECT_THAT(dump, HasSubstr(std::string("[") + kPhantomStudy + "]"));
  EXPECT_THAT(dump, HasSubstr("[Voxray 3D]"));
  EXPECT_THAT(dump, HasSubstr("(0028,0301) CS [NO]"));  // BurnedInAnnotation
  EXPECT_THAT(dump, HasSubstr("(0028,0008) IS [2]"));   // NumberOfFrames
}

// "Opens in Voxray": the importer loads an uncompressed RGB SC as its luminance (Rec. 601,
// rounded: exact integers, no tolerance), one slice per frame, saying so in a warning.
TEST(SecondaryCaptureTest, VoxrayOpensItAsItsLuminanceOneSlicePerFrame) {
  Volume v = loadVolume(writeShot(tempFolder("sc")));
  ASSERT_EQ(v.dims, glm::ivec3(64, 48, 2));
  EXPECT_THAT(testing::PrintToString(v.warnings), HasSubstr("shown as their luminance"));
  const std::vector<Image> shot = frames();
  int wrong = 0;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 64; ++x) {
        const uint8_t* p = shot[size_t(z)].pixel(x, y);
        int luma = (299 * p[0] + 587 * p[1] + 114 * p[2] + 500) / 1000;
        double stored = v.voxels[(size_t(z) * 48 + size_t(y)) * 64 + size_t(x)];
        wrong += stored * v.slope + v.intercept != luma;
      }
  EXPECT_EQ(wrong, 0);
}

// What it says of FILE: dciodvfy's (Debian dicom3tools) checks of the IOD's modules.
std::string dciodvfy(const std::string& file) {
  return runCommand("dciodvfy " + file + " 2>&1").output;
}

int errorLines(const std::string& report) {
  int n = 0;
  for (size_t at = 0; (at = report.find("Error", at)) != std::string::npos; ++at)
    n += at == 0 || report[at - 1] == '\n';
  return n;
}

// An independent validator finds no error in one frame or several. One frame carries no
// Frame Increment Pointer (Type 1C: only for several frames); the patient's birth date and
// sex stay empty (the SC copies only what filing needs); the study keeps its Study ID.
TEST(SecondaryCaptureTest, DciodvfyFindsNoErrorInOneFrameOrTwo) {
  SecondaryCaptureInfo info;
  info.study = loadVolume(dicomPath("ct-philips-phantom/S2010")).study;
  const std::string folder = tempFolder("sc");
  for (size_t count : {1u, 2u}) {
    const std::string path = folder + "/shot" + std::to_string(count) + ".dcm";
    std::vector<Image> shot = frames();
    shot.resize(count, Image(64, 48));
    writeSecondaryCapture(path, shot, info);
    const std::string report = dciodvfy(path);
    ASSERT_THAT(report, HasSubstr("MultiframeTrueColorSCImage")) << report;
    EXPECT_EQ(errorLines(report), 0) << count << " frame(s):\n" << report;
    DcmFileFormat file;
    ASSERT_TRUE(file.loadFile(path.c_str()).good());
    DcmDataset* d = file.getDataset();
    EXPECT_EQ(d->tagExists(DCM_FrameIncrementPointer), count > 1);
    OFString birth = "x", sex = "x", studyId;
    d->findAndGetOFString(DCM_PatientBirthDate, birth);
    d->findAndGetOFString(DCM_PatientSex, sex);
    d->findAndGetOFString(DCM_StudyID, studyId);
    EXPECT_EQ(birth, "");
    EXPECT_EQ(sex, "");
    EXPECT_EQ(std::string(studyId.c_str()), info.study.studyId);
    EXPECT_FALSE(info.study.studyId.empty());
  }
}

TEST(SecondaryCaptureTest, UnequalFramesAreRefused) {
  std::vector<Image> two = {Image(4, 4), Image(4, 5)};
  EXPECT_THROW(writeSecondaryCapture(tempFolder("sc") + "/x.dcm", two, {}), Error);
}

// Sends the SC, finds its new series in the phantom study, retrieves it, compares pixels.
void expectSentScComesBack(const PacsNode& node) {
  auto client = makePacsClient(node);
  PacsQuery q;
  q.level = QueryLevel::Series;
  q.studyInstanceUid = kPhantomStudy;
  auto before = client->find(q);
  client->store({writeShot(tempFolder("sc"))});
  auto series = client->find(q);
  ASSERT_EQ(series.size(), before.size() + 1);  // one new series in the same study
  auto sc = std::find_if(series.begin(), series.end(), [&](const PacsMatch& m) {
    return std::none_of(before.begin(), before.end(), [&](const PacsMatch& b) {
      return b.seriesInstanceUid == m.seriesInstanceUid;
    });
  });
  ASSERT_NE(sc, series.end());
  EXPECT_EQ(sc->seriesDescription, "Voxray 3D");
  EXPECT_EQ(sc->modalities, "OT");
  std::string folder = tempFolder("sc-back");
  auto files = client->retrieveSeries(kPhantomStudy, sc->seriesInstanceUid, folder, {});
  ASSERT_EQ(files.size(), 1u);
  DcmFileFormat back;
  ASSERT_TRUE(back.loadFile(files[0].c_str()).good());
  const Uint8* pixels = nullptr;
  unsigned long count = 0;
  ASSERT_TRUE(back.getDataset()->findAndGetUint8Array(DCM_PixelData, pixels, &count).good());
  std::vector<uint8_t> expected = rgbOf(frames());
  ASSERT_EQ(count, expected.size());
  EXPECT_TRUE(std::equal(expected.begin(), expected.end(), pixels));  // exact: lossless path
}

using ScSendTest = PacsTest;

// C-STORE then C-FIND and C-GET; STOW-RS then QIDO-RS and WADO-RS.
TEST_F(ScSendTest, SentOverEitherTransportItIsFoundWithTheExportedPixels) {
  for (const PacsNode& node : {server().dimseNode(), server().webNode()}) {
    SCOPED_TRACE(node.label());
    expectSentScComesBack(node);
  }
}

// Runs a command; returns its exit status and stdout with stderr.
std::pair<int, std::string> run(const std::string& command) {
  CommandResult r = runCommand(command + " 2>&1");
  return {r.exitCode, std::move(r.output)};
}

using ScPatientTest = PacsTest;  // its own Orthanc: the phantom study gains a series here

// The SC carries the source's patient name and ID (HEAD, PLASTIC) in its header, so that the
// PACS files it under the same patient and study (one study, one more series; not a second
// patient with a study of the same UID). They appear nowhere else: not in the file's name,
// nor in what voxray-cli prints when the send succeeds or fails.
TEST_F(ScPatientTest, PatientFieldsFileTheScWithItsPatientAndAppearNowhereElse) {
  const std::string folder = tempFolder("sc");
  const std::string path = writeShot(folder);
  auto [dumped, dump] = run("dcmdump " + path);
  ASSERT_EQ(dumped, 0) << dump;
  EXPECT_THAT(dump, HasSubstr("(0010,0010) PN [HEAD]"));
  EXPECT_THAT(dump, HasSubstr("(0010,0020) LO [PLASTIC]"));
  for (const auto& f : std::filesystem::recursive_directory_iterator(folder))
    EXPECT_THAT(f.path().string(), testing::AllOf(testing::Not(HasSubstr("HEAD")),
                                                  testing::Not(HasSubstr("PLASTIC"))));
  const PacsNode node = server().dimseNode();
  auto [sent, sendOut] =
      run(std::string(VOXRAY_CLI) + " pacs send dicom://" + node.label() + " " + path);
  EXPECT_EQ(sent, 0) << sendOut;
  PacsNode wrongAe = node;
  wrongAe.calledAe = "NOT_ORTHANC";
  auto [refused, refusedOut] =
      run(std::string(VOXRAY_CLI) + " pacs send dicom://" + wrongAe.label() + " " + path);
  EXPECT_NE(refused, 0);
  EXPECT_THAT(refusedOut, HasSubstr("refused Voxray"));
  for (const std::string& out : {sendOut, refusedOut})
    EXPECT_THAT(
        out, testing::AllOf(testing::Not(HasSubstr("HEAD")), testing::Not(HasSubstr("PLASTIC"))));
  PacsQuery q;
  q.patientId = "PLASTIC";
  auto studies = makePacsClient(node)->find(q);
  ASSERT_EQ(studies.size(), 1u);
  EXPECT_EQ(studies[0].studyInstanceUid, kPhantomStudy);
  EXPECT_EQ(studies[0].numberOfSeries, 3 + 1);
  EXPECT_EQ(studies[0].patientName, "HEAD");
}

}  // namespace
}  // namespace voxray::test
