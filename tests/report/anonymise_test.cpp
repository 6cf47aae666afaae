// The anonymised export opens as the same volume (voxels, geometry) on the shared real
// series, and refuses what would write into the user's data or over an export.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>

#include "voxray/io/anonymise.h"
#include "voxray/io/error.h"
#include "voxray/io/key_object_selection.h"
#include "voxray/io/load.h"
#include "voxray/io/measurement_report.h"

namespace fs = std::filesystem;
using namespace voxray;

namespace {

const std::string kData = VOXRAY_DATA_DIR "/dicom/";

fs::path freshDir(const std::string& name) {
  fs::path p = fs::path(VOXRAY_TEST_TMP) / name;
  fs::remove_all(p);
  fs::create_directories(p.parent_path());
  return p;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

void expectSameVolume(const std::string& series) {
  const fs::path out = freshDir("same-" + series);
  const AnonymiseResult r = anonymise(kData + series, out.string(), {});
  const Volume a = loadVolume(kData + series), b = loadVolume(out.string());
  EXPECT_GT(r.written, 0u);
  // Exact: the geometry comes from the same DS strings and the same pixel bytes.
  EXPECT_EQ(a.dims, b.dims);
  EXPECT_EQ(a.spacingMm, b.spacingMm);
  EXPECT_EQ(a.originMm, b.originMm);
  EXPECT_EQ(a.direction, b.direction);
  EXPECT_EQ(a.slope, b.slope);
  EXPECT_EQ(a.intercept, b.intercept);
  ASSERT_EQ(a.voxelCount(), b.voxelCount());
  EXPECT_TRUE(std::equal(a.voxels.begin(), a.voxels.end(), b.voxels.begin()));
  EXPECT_NE(a.study.studyInstanceUid, b.study.studyInstanceUid);
  EXPECT_NE(a.study.seriesInstanceUid, b.study.seriesInstanceUid);
  EXPECT_EQ(b.study.patientName, "ANONYMOUS");
  EXPECT_EQ(b.study.patientBirthDate, "");
  EXPECT_EQ(b.study.studyDate, "");
  // Slice k is still one file each, with its own new UID.
  ASSERT_EQ(a.study.sliceSopInstanceUids.size(), b.study.sliceSopInstanceUids.size());
  for (size_t k = 0; k < a.study.sliceSopInstanceUids.size(); ++k)
    EXPECT_NE(a.study.sliceSopInstanceUids[k], b.study.sliceSopInstanceUids[k]);
}

}  // namespace

TEST(Anonymise, PelvisOpensAsTheSameVolume) { expectSameVolume("ct-visible-human-pelvis"); }

// Tilted, unevenly spaced: resampled on load, from the anonymised files exactly as before.
TEST(Anonymise, TiltedSeriesOpensAsTheSameVolume) { expectSameVolume("ct-ge-tilt"); }

TEST(Anonymise, ShiftedDatesMoveByTheDays) {
  const fs::path out = freshDir("shift");
  AnonymiseOptions o;
  o.dates = DateHandling::Shift;
  o.shiftDays = -40;
  anonymise(kData + "ct-visible-human-pelvis", out.string(), o);
  const Volume a = loadVolume(kData + "ct-visible-human-pelvis"), b = loadVolume(out.string());
  ASSERT_EQ(a.study.studyDate, "20050101");  // the source's, read by the same loader
  EXPECT_EQ(b.study.studyDate, "20041122");  // 40 days earlier, across a year's end
}

TEST(Anonymise, RefusesToWriteIntoTheSourceFolder) {
  const std::string src = kData + "ct-visible-human-pelvis";
  EXPECT_NE(errorOf([&] {
              anonymise(src, src + "/anon", {});
            }).find("lies inside the input's folder; never written into"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(src + "/anon"));
  EXPECT_NE(errorOf([&] { anonymise(src, src, {}); }).find("lies inside"), std::string::npos);
}

TEST(Anonymise, RefusesAnExistingExportWithoutForce) {
  const fs::path out = freshDir("existing");
  fs::create_directories(out);
  std::ofstream(out / "keep.txt") << "mine";
  const std::string src = kData + "ct-ge-tilt";
  EXPECT_NE(errorOf([&] {
              anonymise(src, out.string(), {});
            }).find("exists and is not empty; give --force"),
            std::string::npos);
  AnonymiseOptions force;
  force.force = true;
  EXPECT_EQ(anonymise(src, out.string(), force).written, 28u);
  EXPECT_TRUE(fs::exists(out / "keep.txt"));
}

TEST(Anonymise, RefusesAFolderWithoutDicom) {
  const fs::path in = freshDir("not-dicom");
  fs::create_directories(in);
  std::ofstream(in / "a.txt") << "not DICOM";
  const fs::path out = freshDir("not-dicom-out");
  EXPECT_NE(errorOf([&] { anonymise(in.string(), out.string(), {}); }).find("no DICOM image under"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(out));  // nothing made for nothing to write
}

TEST(Anonymise, OnlyTheChosenSeries) {
  const std::string src = kData + "ct-visible-human-pelvis";
  AnonymiseOptions o;
  o.seriesUid = "1.2.3.4.not.there";
  EXPECT_NE(errorOf([&] {
              anonymise(src, freshDir("no-series").string(), o);
            }).find("in series 1.2.3.4.not.there"),
            std::string::npos);
}

TEST(Report, RefusesAVolumeNotReadFromDicom) {
  Volume v;
  v.dims = {4, 4, 4};
  v.voxels.assign(64, 0);
  ReportMeasurement m;
  m.points = {{0, 0, 1}, {3, 0, 1}};
  m.value = 3.0;
  EXPECT_NE(errorOf([&] {
              writeMeasurementReport(freshDir("x.dcm").string(), v, {m});
            }).find("open a DICOM series"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              writeKeyObjectSelection(freshDir("k.dcm").string(), v, {1});
            }).find("not read from DICOM"),
            std::string::npos);
}

TEST(KeyImages, RefusesAResampledSeriesAndBadSlices) {
  const Volume tilt = loadVolume(kData + "ct-ge-tilt");
  EXPECT_NE(errorOf([&] {
              writeKeyObjectSelection(freshDir("t.dcm").string(), tilt, {1});
            }).find("not its files' images"),
            std::string::npos);
  const Volume pelvis = loadVolume(kData + "ct-visible-human-pelvis");
  EXPECT_NE(errorOf([&] {
              writeKeyObjectSelection(freshDir("p.dcm").string(), pelvis, {150});
            }).find("Slice 150 is not in the series: give 0..149"),
            std::string::npos);
  EXPECT_NE(errorOf([&] {
              writeKeyObjectSelection(freshDir("p.dcm").string(), pelvis, {3, 3});
            }).find("given twice"),
            std::string::npos);
}

// Pixels that show text cannot be cleaned by the Basic Profile alone: such images stay out.
TEST(Anonymise, LeavesOutImagesWithBurnedInText) {
  const fs::path in = freshDir("burned-in");
  fs::create_directories(in);
  const std::string src = kData + "ct-ge-tilt/";
  for (const char* name : {"01.dcm", "02.dcm"}) {
    DcmFileFormat f;
    ASSERT_TRUE(f.loadFile((src + name).c_str()).good());
    if (std::string(name) == "02.dcm")
      f.getDataset()->putAndInsertString(DCM_BurnedInAnnotation, "YES");
    ASSERT_TRUE(f.saveFile((in / name).c_str()).good());
  }
  const AnonymiseResult r = anonymise(in.string(), freshDir("burned-in-out").string(), {});
  EXPECT_EQ(r.written, 1u);
  EXPECT_EQ(r.burnedIn, 1u);
}

// The writers' success paths in this binary too (it runs under ASan in scripts/test; the
// values are checked by check_sr.py and check_kos.py through voxray-cli): the returned UID is
// the file's.
TEST(Report, WritesAReportAndKeyImagesOfThePelvis) {
  const Volume v = loadVolume(kData + "ct-visible-human-pelvis");
  ReportMeasurement roi;
  roi.kind = ReportKind::Ellipse;
  roi.points = {{240, 90, 1}, {260, 110, 1}};
  roi.mean = -1001.0, roi.sd = 10.0, roi.min = -1024.0, roi.max = -971.0;
  roi.areaMm2 = 314.159;
  ReportMeasurement across;
  across.points = {{10, 10, 0}, {20, 20, 3}};
  across.value = 14.4568;
  const fs::path sr = freshDir("sr.dcm"), kos = freshDir("kos.dcm");
  const WrittenReport r = writeMeasurementReport(sr.string(), v, {roi, across});
  // The line spans slices 0 and 3 of a series with a Frame of Reference: its points go in as
  // SCOORD3D (issue 37), and the note says so.
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_NE(r.notes[0].find("patient coordinates (SCOORD3D, LPS mm)"), std::string::npos)
      << r.notes[0];
  const std::string k = writeKeyObjectSelection(kos.string(), v, {10, 20, 5});
  for (const auto& [path, uid] : {std::pair{sr, r.sopInstanceUid}, std::pair{kos, k}}) {
    DcmFileFormat f;
    ASSERT_TRUE(f.loadFile(path.c_str()).good());
    OFString written;
    f.getDataset()->findAndGetOFString(DCM_SOPInstanceUID, written);
    EXPECT_EQ(uid, written.c_str());
  }
}
