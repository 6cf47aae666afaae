// The local study database on the shared real scans: import, search, priors, delete,
// verify, rebuild from the journal, and opening a series from it.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>

#include "studydb_test_support.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"
#include "voxray/studydb/study_db.h"

namespace fs = std::filesystem;
using testing::ElementsAre;
using testing::HasSubstr;

namespace voxray::test {
namespace {

// Facts read with pydicom (dcmread, stop_before_pixels) from the shared scans:
// ct-philips-phantom: 1 study (1A TRAUMA/PLAIN HEAD DM, 20150206, patient ID PLASTIC) of 3
//   CT series: 201 (28 images, body part BRAIN), 401 (6), 100 (1); 4 DICOMDIRs (DIRFILE)
//   and LICENSE are no instances.
// ct-ge-tilt: 1 study (HEAD, no study date), 1 CT series (2, HEAD) of 28 images; LICENSE.
// ct-visible-human-pelvis: 1 study (Visible Human Female, 20050101, ID 000-000-001),
//   1 CT series of 150 images.
const std::string kPhilipsVolume = "1.3.46.670589.33.1.6002432791750815306.26862469513794233732";
const std::string kPelvisSeries = "1.2.826.0.1.3680043.2.1125.1.75064541463040.2005072610384286453";

std::vector<std::string> uids(const std::vector<StudyRow>& rows) {
  std::vector<std::string> out;
  for (const auto& r : rows) out.push_back(r.study.uid);
  return out;
}

// Every row the database shows, as text: the same text is the same database.
std::string dump(StudyDb& db) {
  std::string out;
  for (const auto& s : db.find({})) {
    out += s.patient.patientId + "|" + s.patient.name + "|" + s.patient.birthDate + "|" +
           s.patient.sex + "|" + s.study.uid + "|" + s.study.date + "|" + s.study.time + "|" +
           s.study.description + "|" + s.study.accession + "|" + s.modalities + "|" +
           std::to_string(s.seriesCount) + "|" + std::to_string(s.instanceCount) + "\n";
    for (const auto& se : db.series(s.study.uid)) {
      out += " " + se.series.uid + "|" + std::to_string(se.series.number) + "|" +
             se.series.description + "|" + se.series.modality + "|" + se.series.bodyPart + "|" +
             std::to_string(se.instanceCount) + "|" + std::to_string(se.frameCount) + "\n";
      for (const auto& i : db.instances(se.series.uid))
        out += "  " + i.instance.path + "|" + i.instance.sopInstanceUid + "|" +
               i.instance.sopClassUid + "|" + std::to_string(i.instance.number) + "|" +
               i.instance.position + "|" + std::to_string(i.instance.frames) + "|" +
               i.instance.transferSyntaxUid + "|" + std::to_string(i.instance.size) + "|" +
               std::to_string(i.instance.stored) + "\n";
    }
  }
  return out;
}

StudyQuery byId(const std::string& id) {
  StudyQuery q;
  q.patientId = id;
  return q;
}

class StudyDbTest : public testing::Test {
 protected:
  void importScans(StudyDb& db) {
    report_ = db.import({dicomPath("ct-philips-phantom"), dicomPath("ct-ge-tilt"),
                         dicomPath("ct-visible-human-pelvis")});
  }
  ImportReport report_;
};

TEST_F(StudyDbTest, ImportCountsStudiesSeriesAndInstancesOfTheRealScans) {
  StudyDb db(tempFolder("db"));
  importScans(db);
  EXPECT_EQ(report_.added, 35 + 28 + 150);
  EXPECT_EQ(report_.updated, 0);
  EXPECT_EQ(report_.studyUids.size(), 3u);
  EXPECT_EQ(report_.seriesUids.size(), 5u);
  EXPECT_EQ(db.studyCount(), 3);
  EXPECT_EQ(db.instanceCount(), 213);
  // 4 DICOMDIRs and 2 LICENSE files, each with its reason.
  ASSERT_EQ(report_.skipped.size(), 6u);
  EXPECT_EQ(report_.notDicom, 2);
  for (const auto& s : report_.skipped) {
    if (fs::path(s.path).filename() == "LICENSE")
      EXPECT_EQ(s.reason, "not a DICOM file");
    else
      EXPECT_THAT(s.reason, HasSubstr("DICOMDIR")) << s.path;
  }
  auto philips = db.study(kPhilipsStudy);
  ASSERT_EQ(philips.size(), 1u);
  EXPECT_EQ(philips[0].study.date, "20150206");
  EXPECT_EQ(philips[0].study.description, "1A TRAUMA/PLAIN HEAD DM");
  EXPECT_EQ(philips[0].patient.patientId, "PLASTIC");
  EXPECT_EQ(philips[0].modalities, "CT");
  EXPECT_EQ(philips[0].seriesCount, 3);
  EXPECT_EQ(philips[0].instanceCount, 35);
  auto series = db.series(kPhilipsStudy);
  ASSERT_EQ(series.size(), 3u);  // by series number
  EXPECT_EQ(series[0].series.number, 100);
  EXPECT_EQ(series[0].instanceCount, 1);
  EXPECT_EQ(series[1].series.number, 201);
  EXPECT_EQ(series[1].series.uid, kPhilipsVolume);
  EXPECT_EQ(series[1].series.bodyPart, "BRAIN");
  EXPECT_EQ(series[1].instanceCount, 28);
  EXPECT_EQ(series[2].series.number, 401);
  EXPECT_EQ(series[2].instanceCount, 6);
  // Instances by number, with their header fields and the file's size.
  auto pelvis = db.instances(kPelvisSeries);
  ASSERT_EQ(pelvis.size(), 150u);
  for (const auto& i : pelvis) {
    EXPECT_TRUE(fs::path(i.instance.path).is_absolute());
    EXPECT_EQ(i.instance.size, fs::file_size(i.instance.path));
    EXPECT_FALSE(i.instance.stored);
    EXPECT_EQ(i.instance.frames, 1);
    EXPECT_THAT(i.instance.position, testing::MatchesRegex(R"([-0-9.]+\\[-0-9.]+\\[-0-9.]+)"));
  }
  // A second import reads nothing again: every file is known, with its size and time.
  ImportReport again = db.import({dicomPath("ct-ge-tilt")});
  EXPECT_EQ(again.unchanged, 28);
  EXPECT_EQ(again.added + again.updated, 0);
}

TEST_F(StudyDbTest, ABrokenFileIsSkippedWithItsReason) {
  std::string data = tempFolder("data");
  // A real slice cut after 300 bytes: it starts as DICOM, its header ends mid-element.
  std::ifstream in(dicomPath("ct-ge-tilt/01.dcm"), std::ios::binary);
  std::string head(300, '\0');
  in.read(head.data(), 300);
  std::ofstream(data + "/cut.dcm", std::ios::binary) << head;
  std::ofstream(data + "/notes.txt") << "not an image\n";
  fs::copy_file(dicomPath("ct-ge-tilt/02.dcm"), data + "/02.dcm");
  // A file without the 128-byte preamble and DICM (as old archives hold): still DICOM.
  std::ifstream whole(dicomPath("ct-ge-tilt/04.dcm"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(whole)), std::istreambuf_iterator<char>());
  std::ofstream(data + "/headerless", std::ios::binary) << bytes.substr(132);
  StudyDb db(tempFolder("db"));
  ImportReport r = db.import({data});
  EXPECT_EQ(r.filesScanned, 4);
  EXPECT_EQ(r.added, 2);
  ASSERT_EQ(r.skipped.size(), 2u);
  EXPECT_EQ(fs::path(r.skipped[0].path).filename(), "cut.dcm");
  EXPECT_THAT(r.skipped[0].reason, HasSubstr("damaged DICOM"));
  EXPECT_EQ(fs::path(r.skipped[1].path).filename(), "notes.txt");
  EXPECT_EQ(r.skipped[1].reason, "not a DICOM file");
  EXPECT_EQ(r.notDicom, 1);
  // A path that does not exist is an error that names it.
  try {
    db.import({data + "/nowhere"});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("nowhere: no such file or folder"));
  }
}

TEST_F(StudyDbTest, SearchByEachKey) {
  StudyDb db(tempFolder("db"));
  importScans(db);
  const std::string tilt = db.find(byId("QMNx85rKkkg")).at(0).study.uid;
  const std::string pelvis = db.find(byId("000-000-001")).at(0).study.uid;
  EXPECT_EQ(db.find({}).size(), 3u);
  // Newest first; the study without a date last.
  EXPECT_THAT(uids(db.find({})), ElementsAre(kPhilipsStudy, pelvis, tilt));
  StudyQuery q;
  q.patientId = "PLAS*";
  EXPECT_THAT(uids(db.find(q)), ElementsAre(kPhilipsStudy));
  q = {};
  q.patientId = "PLAS";  // an ID without wildcards is matched whole
  EXPECT_TRUE(db.find(q).empty());
  q = {};
  q.dateFrom = "20040101";
  q.dateTo = "20051231";
  EXPECT_THAT(uids(db.find(q)), ElementsAre(pelvis));
  q.dateTo = "20150206";  // inclusive
  EXPECT_THAT(uids(db.find(q)), ElementsAre(kPhilipsStudy, pelvis));
  q = {};
  q.modality = "ct";
  EXPECT_EQ(db.find(q).size(), 3u);
  q.modality = "MR";
  EXPECT_TRUE(db.find(q).empty());
  q = {};
  q.description = "visible human";  // any part, any case
  EXPECT_THAT(uids(db.find(q)), ElementsAre(pelvis));
  q.description = "trauma";
  EXPECT_THAT(uids(db.find(q)), ElementsAre(kPhilipsStudy));
  // Each study's patient name, found by a part of it.
  for (const auto& s : db.find({})) {
    if (s.patient.name.size() < 3) continue;
    q = {};
    q.patientName = s.patient.name.substr(1, s.patient.name.size() - 2);
    EXPECT_THAT(uids(db.find(q)), testing::Contains(s.study.uid));
  }
  q = {};
  q.patientName = "no such patient";
  EXPECT_TRUE(db.find(q).empty());
  q = {};
  q.limit = 1;
  EXPECT_EQ(db.find(q).size(), 1u);
}

InstanceRecord record(const std::string& patient, const std::string& study, const std::string& date,
                      const std::string& modality, const std::string& part) {
  InstanceRecord r;
  r.patient = {patient, "TEST^" + patient, "19600101", "F"};
  r.study = {study, date, "120000", "study " + study, "", ""};
  r.series = {study + ".1", "series", modality, part, 1};
  r.instance.path = "/nonexistent/" + study + ".dcm";
  r.instance.sopInstanceUid = study + ".1.1";
  return r;
}

TEST_F(StudyDbTest, PriorsSameModalityAndBodyPartFirstThenNewestFirst) {
  StudyDb db(tempFolder("db"));
  db.importRecords({record("P1", "1.9.5", "20240301", "CT", "HEAD"),  // the current study
                    record("P1", "1.9.1", "20200101", "CT", "HEAD"),
                    record("P1", "1.9.2", "20220101", "MR", "HEAD"),
                    record("P1", "1.9.3", "20210101", "CT", "CHEST"),
                    record("P1", "1.9.4", "20190101", "CT", "HEAD"),
                    record("P1", "1.9.6", "20250101", "CT", "HEAD"),   // later: no prior
                    record("P2", "1.9.7", "20180101", "CT", "HEAD")},  // another patient
                   false);
  EXPECT_THAT(uids(db.priors("1.9.5")), ElementsAre("1.9.1", "1.9.4", "1.9.3", "1.9.2"));
  EXPECT_TRUE(db.priors("1.9.4").empty());
  EXPECT_THROW(db.priors("1.9.99"), Error);
}

TEST_F(StudyDbTest, DeleteRemovesRowsAndOnlyTheStoresCopies) {
  StudyDb db(tempFolder("db"));
  importScans(db);
  ImportOptions copy;
  copy.copy = true;
  std::string data = tempFolder("data");
  fs::copy_file(dicomPath("ct-ge-tilt/03.dcm"), data + "/03.dcm");
  db.deleteStudy(db.find(byId("QMNx85rKkkg")).at(0).study.uid);
  ImportReport r = db.import({data}, copy);
  ASSERT_EQ(r.added, 1);
  auto stored = db.instances(kTiltSeries).at(0).instance;
  EXPECT_TRUE(stored.stored);
  EXPECT_THAT(stored.path, testing::StartsWith(db.folder() + "/store/"));
  EXPECT_EQ(db.deleteSeries(kTiltSeries), 1);
  EXPECT_FALSE(fs::exists(stored.path));      // the database's own copy
  EXPECT_TRUE(fs::exists(data + "/03.dcm"));  // the user's file stays
  EXPECT_EQ(db.studyCount(), 2);              // a study left with no series goes
  EXPECT_EQ(db.deleteStudy(kPhilipsStudy), 35);
  EXPECT_TRUE(fs::exists(dicomPath("ct-philips-phantom/S2010")));
  EXPECT_EQ(db.studyCount(), 1);
  EXPECT_EQ(db.deleteStudy(kPhilipsStudy), 0);
}

TEST_F(StudyDbTest, VerifyFindsDeletedAndChangedFiles) {
  std::string data = tempFolder("data");
  for (const char* f : {"01.dcm", "02.dcm", "03.dcm"})
    fs::copy_file(dicomPath(std::string("ct-ge-tilt/") + f), data + "/" + f);
  StudyDb db(tempFolder("db"));
  ASSERT_EQ(db.import({data}).added, 3);
  VerifyReport clean = db.verify();
  EXPECT_EQ(clean.checked, 3);
  EXPECT_EQ(clean.ok, 3);
  fs::remove(data + "/02.dcm");
  std::ofstream(data + "/03.dcm", std::ios::app) << "x";
  VerifyReport r = db.verify();
  EXPECT_EQ(r.checked, 3);
  EXPECT_EQ(r.ok, 1);
  EXPECT_THAT(r.missing, ElementsAre(data + "/02.dcm"));
  EXPECT_THAT(r.changed, ElementsAre(data + "/03.dcm"));
  auto series = db.series(db.find({}).at(0).study.uid);
  ASSERT_EQ(series.size(), 1u);
  EXPECT_EQ(series[0].missing, 1);
  EXPECT_EQ(series[0].changed, 1);
  // Importing the changed file again makes it whole.
  EXPECT_EQ(db.import({data}).updated, 1);
  EXPECT_TRUE(db.verify().changed.empty());
}

TEST_F(StudyDbTest, RebuildFromTheJournalGivesTheSameRows) {
  std::string folder = tempFolder("db");
  std::string before;
  {
    StudyDb db(folder);
    importScans(db);
    db.deleteSeries(kPelvisSeries);  // a deletion is replayed too
    before = dump(db);
    ASSERT_EQ(db.studyCount(), 2);
    db.rebuild();
    EXPECT_EQ(dump(db), before);
  }
  // A damaged database file: rebuilt when opened, saying so.
  {
    std::fstream f(folder + "/studies.sqlite", std::ios::in | std::ios::out | std::ios::binary);
    f.write("this is no longer a database file", 33);
  }
  StudyDb reopened(folder);
  EXPECT_TRUE(reopened.rebuiltOnOpen());
  EXPECT_EQ(dump(reopened), before);
  EXPECT_EQ(reopened.instanceCount(), 35 + 28);
}

TEST_F(StudyDbTest, ASeriesFromTheDatabaseOpensTheSameVoxelsAsItsFolder) {
  StudyDb db(tempFolder("db"));
  importScans(db);
  for (const auto& [uid, folder] : {std::pair{kTiltSeries, std::string("ct-ge-tilt")},
                                    std::pair{kPhilipsVolume, std::string("ct-philips-phantom")}}) {
    SeriesInput in = db.seriesInput(uid);
    EXPECT_THAT(in.folder, testing::StartsWith(db.folder() + "/views/"));
    LoadOptions o;
    o.series = in.series;
    Volume fromDb = loadVolume(in.folder, o);
    LoadOptions direct;
    direct.series = uid;
    Volume fromFolder = loadVolume(dicomPath(folder), direct);
    ASSERT_EQ(fromDb.dims, fromFolder.dims) << folder;
    EXPECT_EQ(fromDb.spacingMm, fromFolder.spacingMm);
    EXPECT_EQ(fromDb.originMm, fromFolder.originMm);
    EXPECT_TRUE(std::equal(fromDb.voxels.begin(), fromDb.voxels.end(), fromFolder.voxels.begin()))
        << folder;
  }
  EXPECT_THROW(db.seriesInput("1.2.3.4.5"), Error);
}

TEST_F(StudyDbTest, SameSopInstanceUidInTwoFilesKeepsBothAndWarns) {
  std::string data = tempFolder("data");
  fs::create_directories(data + "/a");
  fs::create_directories(data + "/b");
  fs::copy_file(dicomPath("ct-ge-tilt/05.dcm"), data + "/a/05.dcm");
  fs::copy_file(dicomPath("ct-ge-tilt/05.dcm"), data + "/b/05.dcm");
  std::ofstream(data + "/b/05.dcm", std::ios::app) << "xx";  // different content
  StudyDb db(tempFolder("db"));
  ImportReport r = db.import({data});
  EXPECT_EQ(r.added, 2);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_THAT(r.warnings[0], HasSubstr("with different content"));
  EXPECT_EQ(db.instances(kTiltSeries).size(), 2u);
  // Copied into the store, both are kept too, side by side; the same file again is not a
  // third copy.
  StudyDb copies(tempFolder("copies"));
  ImportOptions copy;
  copy.copy = true;
  ImportReport c = copies.import({data}, copy);
  EXPECT_EQ(c.added, 2);
  EXPECT_EQ(c.warnings.size(), 1u);
  EXPECT_EQ(copies.import({data + "/a"}, copy).updated, 1);
  auto stored = copies.instances(kTiltSeries);
  ASSERT_EQ(stored.size(), 2u);
  EXPECT_NE(stored[0].instance.size, stored[1].instance.size);
  for (const auto& i : stored) EXPECT_TRUE(fs::exists(i.instance.path));
}

// A database the user put inside the folder they import: its own files (the SQLite file,
// the journal, the store's copies, the series views) are never taken for the user's.
TEST_F(StudyDbTest, TheDatabasesOwnFilesAreNeverImported) {
  std::string data = tempFolder("data");
  fs::copy_file(dicomPath("ct-ge-tilt/06.dcm"), data + "/06.dcm");
  fs::copy_file(dicomPath("ct-ge-tilt/07.dcm"), data + "/07.dcm");
  StudyDb db(data + "/studies");
  ImportOptions copy;
  copy.copy = true;
  EXPECT_EQ(db.import({data}, copy).added, 2);
  db.seriesInput(kTiltSeries);  // makes views/ with links
  ImportReport again = db.import({data});
  EXPECT_EQ(again.filesScanned, 2);
  EXPECT_TRUE(again.skipped.empty());
  EXPECT_EQ(db.instanceCount(), 4);  // the 2 copies and the 2 files where they are
}

}  // namespace
}  // namespace voxray::test
