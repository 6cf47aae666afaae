// The study browser's model on a database made from the shared real scans: counts, search,
// patient grouping, priors order, import in the background, moved files, delete, a PACS
// retrieval stored in the database, and thumbnails.
#include <filesystem>
#include <map>

#include <gmock/gmock.h>

#include "study_browser_model.h"
#include "studydb_test_support.h"
#include "thumbnail.h"
#include "voxray/io/error.h"
#include "voxray/io/load.h"
#include "voxray/io/volume.h"

namespace fs = std::filesystem;
using testing::ElementsAre;

namespace voxray::test {
namespace {

// Facts read with pydicom (dcmread, stop_before_pixels) from the shared scans (as in
// tests/studydb): ct-philips-phantom 1 study 20150206 "1A TRAUMA/PLAIN HEAD DM", patient ID
// PLASTIC, name HEAD, CT series 100 (1 image), 201 (28, body part BRAIN, 512 x 512),
// 401 (6); ct-ge-tilt 1 study without a date, ID QMNx85rKkkg, 1 series of 28; ct-visible-
// human-pelvis 1 study 20050101, ID 000-000-001, name Eve, 1 series of 150.
const std::string kPhilipsStudy = "1.3.46.670589.33.1.27492712521914879309.27169771283235650014";
const std::string kPhilipsVolume = "1.3.46.670589.33.1.6002432791750815306.26862469513794233732";

std::vector<std::string> uids(const std::vector<StudyRow>& rows) {
  std::vector<std::string> out;
  for (const auto& r : rows) out.push_back(r.study.uid);
  return out;
}

// Imports the three real studies through the model's background import.
void importScans(StudyBrowserModel& m) {
  m.importPaths({dicomPath("ct-philips-phantom"), dicomPath("ct-ge-tilt"),
                 dicomPath("ct-visible-human-pelvis")});
  m.waitForImport();
}

struct Recorder {
  ImportReport report;
  std::string failure;
  int progressCalls = 0, lastDone = 0, lastTotal = 0;
  std::map<std::string, Image> thumbnails;
  StudyBrowserEvents events() {
    StudyBrowserEvents e;
    e.importProgress = [this](int d, int t) {
      ++progressCalls;
      lastDone = d;
      lastTotal = t;
    };
    e.imported = [this](const ImportReport& r) { report = r; };
    e.importFailed = [this](const std::string& m) { failure = m; };
    e.thumbnail = [this](const std::string& uid, const Image& i) { thumbnails[uid] = i; };
    return e;
  }
};

TEST(StudyBrowserModel, ImportInTheBackgroundThenPatientsStudiesAndSeries) {
  Recorder rec;
  StudyBrowserModel m(tempFolder("db"), rec.events());
  EXPECT_EQ(m.studyCount(), 0);
  importScans(m);
  EXPECT_EQ(rec.failure, "");
  EXPECT_EQ(rec.report.added, 35 + 28 + 150);  // every image of the three studies
  EXPECT_GT(rec.progressCalls, 0);
  EXPECT_EQ(rec.lastDone, rec.lastTotal);
  EXPECT_FALSE(m.importing());
  m.search({});
  ASSERT_EQ(m.studies().size(), 3u);
  // Newest first; the study without a date last.
  EXPECT_EQ(m.studies()[0].study.uid, kPhilipsStudy);
  EXPECT_EQ(m.studies()[1].patient.patientId, "000-000-001");
  EXPECT_EQ(m.studies()[2].patient.patientId, "QMNx85rKkkg");
  ASSERT_EQ(m.patients().size(), 3u);
  EXPECT_EQ(m.patients()[0].patient.patientId, "PLASTIC");
  EXPECT_THAT(m.patients()[0].studies, ElementsAre(0u));
  auto series = m.series(kPhilipsStudy);
  ASSERT_EQ(series.size(), 3u);
  EXPECT_EQ(series[0].row.series.number, 100);
  EXPECT_EQ(series[0].row.instanceCount, 1);
  EXPECT_EQ(series[1].row.series.uid, kPhilipsVolume);
  EXPECT_EQ(series[1].row.instanceCount, 28);
  EXPECT_EQ(series[2].row.instanceCount, 6);
  for (const auto& s : series) EXPECT_EQ(s.missingFiles, 0);
}

TEST(StudyBrowserModel, SearchNarrowsByEachField) {
  StudyBrowserModel m(tempFolder("db"));
  importScans(m);
  StudyQuery q;
  q.patientName = "ev";  // a part of "Eve", any case
  m.search(q);
  ASSERT_EQ(m.studies().size(), 1u);
  EXPECT_EQ(m.studies()[0].patient.patientId, "000-000-001");
  q = {};
  q.patientId = "PLASTIC";
  m.search(q);
  EXPECT_THAT(uids(m.studies()), ElementsAre(kPhilipsStudy));
  q = {};
  q.dateFrom = "20040101";
  q.dateTo = "20150206";  // inclusive at both ends; the undated study is outside any range
  m.search(q);
  EXPECT_EQ(m.studies().size(), 2u);
  q = {};
  q.modality = "CT";
  m.search(q);
  EXPECT_EQ(m.studies().size(), 3u);
  EXPECT_EQ(m.patients().size(), 3u);
  q.modality = "MR";
  m.search(q);
  EXPECT_TRUE(m.studies().empty());
  EXPECT_TRUE(m.patients().empty());
  q = {};
  q.description = "TRAUMA";
  m.search(q);
  EXPECT_THAT(uids(m.studies()), ElementsAre(kPhilipsStudy));
}

InstanceRecord priorRecord(const PatientFields& patient, const std::string& uid,
                           const std::string& date, const std::string& modality,
                           const std::string& part) {
  InstanceRecord r;
  r.patient = patient;
  r.study = {uid, date, "120000", "prior " + uid, "", ""};
  r.series = {uid + ".1", "series", modality, part, 1};
  r.instance.path = "/nonexistent/" + uid + ".dcm";
  r.instance.sopInstanceUid = uid + ".1.1";
  return r;
}

TEST(StudyBrowserModel, PriorsOfTheRealStudyInComparisonOrder) {
  const std::string folder = tempFolder("db");
  StudyBrowserModel m(folder);
  importScans(m);
  m.search({});
  const PatientFields plastic = m.studies()[0].patient;
  {
    // Earlier studies of the phantom's patient, as a PACS or an older import would add them.
    StudyDb db(folder);
    db.importRecords({priorRecord(plastic, "1.9.1", "20100101", "CT", "BRAIN"),
                      priorRecord(plastic, "1.9.2", "20140101", "MR", "BRAIN"),
                      priorRecord(plastic, "1.9.3", "20120101", "CT", "CHEST"),
                      priorRecord(plastic, "1.9.4", "20130101", "CT", "BRAIN"),
                      priorRecord(plastic, "1.9.5", "20200101", "CT", "BRAIN")},  // later
                     false);
  }
  // CT of the brain first (newest first), then CT elsewhere, then the MR; never the later one.
  EXPECT_THAT(uids(m.priors(kPhilipsStudy)), ElementsAre("1.9.4", "1.9.1", "1.9.3", "1.9.2"));
  m.search({});
  EXPECT_EQ(m.studies().size(), 3u + 5u);
  ASSERT_EQ(m.patients()[0].patient.patientId, "PLASTIC");  // the 2020 study is the newest
  EXPECT_EQ(m.patients()[0].studies.size(), 6u);
  EXPECT_EQ(m.patients().size(), 3u);
}

TEST(StudyBrowserModel, OpenSeriesGivesTheVolumeOfItsFolder) {
  StudyBrowserModel m(tempFolder("db"));
  importScans(m);
  auto [folder, options] = m.openSeries(kPhilipsVolume);
  Volume fromDb = loadVolume(folder, options);
  LoadOptions direct;
  direct.series = kPhilipsVolume;
  Volume fromFolder = loadVolume(dicomPath("ct-philips-phantom"), direct);
  EXPECT_EQ(fromDb.dims, glm::ivec3(512, 512, 28));
  EXPECT_EQ(fromDb.dims, fromFolder.dims);
  EXPECT_EQ(fromDb.spacingMm, fromFolder.spacingMm);
  EXPECT_THROW(m.openSeries("1.2.3.no.such.series"), Error);
}

TEST(StudyBrowserModel, MovedFilesAreCountedAndAnEmptySeriesIsRefused) {
  const std::string data = tempFolder("data");
  fs::copy(dicomPath("ct-ge-tilt"), data, fs::copy_options::recursive);
  StudyBrowserModel m(tempFolder("db"));
  m.importPaths({data});
  m.waitForImport();
  m.search({});
  ASSERT_EQ(m.studies().size(), 1u);
  const std::string study = m.studies()[0].study.uid;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(data))
    if (e.path().filename() != "LICENSE") files.push_back(e.path());
  ASSERT_EQ(files.size(), 28u);
  fs::remove(files[0]);
  auto series = m.series(study);
  ASSERT_EQ(series.size(), 1u);
  EXPECT_EQ(series[0].missingFiles, 1);
  EXPECT_EQ(missingText(series[0]), "1 of 28 files missing");
  fs::rename(data, data + ".moved");
  series = m.series(study);
  EXPECT_EQ(series[0].missingFiles, 28);
  EXPECT_TRUE(series[0].allMissing());
  EXPECT_EQ(missingText(series[0]), "files missing (moved or deleted)");
  EXPECT_THROW(m.openSeries(series[0].row.series.uid), Error);
  fs::remove_all(data + ".moved");
}

TEST(StudyBrowserModel, DeleteRemovesTheStudyAndSearchesAgain) {
  auto fileCount = [] {
    int n = 0;
    for (const auto& e : fs::recursive_directory_iterator(dicomPath("ct-philips-phantom")))
      n += e.is_regular_file();
    return n;
  };
  const int filesBefore = fileCount();
  StudyBrowserModel m(tempFolder("db"));
  importScans(m);
  m.search({});
  EXPECT_EQ(m.deleteStudy(kPhilipsStudy), 35);
  EXPECT_EQ(m.studies().size(), 2u);
  EXPECT_EQ(m.studyCount(), 2);
  EXPECT_EQ(fileCount(), filesBefore);  // the user's files stay
}

TEST(StudyBrowserModel, ARetrievedStudyIsFoundLocallyAfterTheCacheLetsItGo) {
  // A PACS cache folder as PacsCache::retrieve leaves it: the study's files.
  const std::string cache = tempFolder("cache");
  fs::copy(dicomPath("ct-ge-tilt"), cache, fs::copy_options::recursive);
  StudyBrowserModel m(tempFolder("db"));
  ImportReport r = m.storeRetrieved(cache);
  EXPECT_EQ(r.added, 28);
  fs::remove_all(cache);  // evicted
  StudyQuery q;
  q.patientId = "QMNx85rKkkg";
  m.search(q);
  ASSERT_EQ(m.studies().size(), 1u);
  auto series = m.series(m.studies()[0].study.uid);
  ASSERT_EQ(series.size(), 1u);
  EXPECT_EQ(series[0].missingFiles, 0);  // copied into the database's store
  auto [folder, options] = m.openSeries(series[0].row.series.uid);
  // The same volume as the original folder gives (its gantry tilt resampled: 172 slices).
  Volume fromDb = loadVolume(folder, options);
  Volume original = loadVolume(dicomPath("ct-ge-tilt"));
  EXPECT_EQ(fromDb.dims, original.dims);
  EXPECT_EQ(fromDb.spacingMm, original.spacingMm);
}

TEST(StudyBrowserModel, ThumbnailsForTheVolumeSeries) {
  Recorder rec;
  StudyBrowserModel m(tempFolder("db"), rec.events());
  importScans(m);
  m.makeThumbnails(kPhilipsStudy);
  m.waitForThumbnails();
  EXPECT_EQ(rec.thumbnails.size(), 3u);  // one event per series, a picture or none
  const Image& t = rec.thumbnails.at(kPhilipsVolume);
  ASSERT_EQ(t.width, 64);  // kThumbnailSize
  ASSERT_EQ(t.height, 64);
  // The same picture as the thumbnail helper makes of the series loaded from its own folder.
  LoadOptions o;
  o.series = kPhilipsVolume;
  Volume v = loadVolume(dicomPath("ct-philips-phantom"), o);
  Image expected = middleSliceThumbnail(v, defaultThumbnailWindow(v, "CT", true));
  EXPECT_EQ(t.rgba, expected.rgba);
  // And not a black square: the head phantom fills about 8% of the 512 mm field (344 of
  // 4096 pixels when measured); more than 5% lit says it shows.
  int lit = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) lit += t.pixel(x, y)[0] > 0;
  EXPECT_GT(lit, 64 * 64 / 20);
}

}  // namespace
}  // namespace voxray::test
