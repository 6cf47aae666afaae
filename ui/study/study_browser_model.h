#pragma once
// The workstation's study browser (File → Study browser…), Qt-free: the local study database
// (io/studydb) searched by name, ID, date range, modality and description, shown as patients
// → studies → series; a study's priors; import of folders and delete; the series' thumbnails;
// and the PACS browser's retrievals stored in the database (as `voxray-cli pacs get --db`
// does), so a retrieved study is found locally the next time. Import and thumbnails run as
// BackgroundTasks with their own database connection (SQLite in WAL mode lets the browser
// search meanwhile); events arrive through POST (the dialog's GUI thread).
// Patient fields are shown to the user who asked for them: never logged, never in messages.
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "background_task.h"
#include "no_qt.h"
#include "voxray/io/image.h"
#include "voxray/io/load.h"

#ifdef VOXRAY_HAS_STUDYDB
#include "voxray/studydb/study_db.h"

namespace voxray {

// One patient of a search: the indexes of their studies in StudyBrowserModel::studies().
struct PatientGroup {
  PatientFields patient;
  std::vector<size_t> studies;
};

// A series as the browser lists it: its row and how many of its files are not where the
// database says (counted when listed, so a moved folder shows at once).
struct SeriesEntry {
  SeriesRow row;
  int missingFiles = 0;
  bool allMissing() const { return row.instanceCount > 0 && missingFiles >= row.instanceCount; }
};

// What the browser shows for a series' files: "" when all are there.
std::string missingText(const SeriesEntry& s);

struct StudyBrowserEvents {
  std::function<void(int done, int total)> importProgress;
  std::function<void(const ImportReport&)> imported;
  std::function<void(const std::string& message)> importFailed;
  // One per series of a makeThumbnails() study; an empty image: none possible (not a volume,
  // too large, files missing).
  std::function<void(const std::string& seriesUid, const Image& thumbnail)> thumbnail;
};

class StudyBrowserModel {
 public:
  // Opens (or makes) FOLDER's database. Throws Error when it cannot be made.
  explicit StudyBrowserModel(std::string folder = defaultStudyDbFolder(),
                             StudyBrowserEvents events = {}, BackgroundTask::Post post = {});
  ~StudyBrowserModel();  // cancels and waits for its tasks
  StudyBrowserModel(const StudyBrowserModel&) = delete;
  StudyBrowserModel& operator=(const StudyBrowserModel&) = delete;

  const std::string& folder() const { return db_->folder(); }
  // The database file was damaged and made again from its journal (say so to the user).
  bool rebuiltOnOpen() const { return db_->rebuiltOnOpen(); }
  // Whether FOLDER holds a database with at least one study, without making one.
  static bool hasStudies(const std::string& folder = defaultStudyDbFolder());

  // Runs QUERY: studies() newest first, patients() grouped by patient ID and name in the
  // order of their newest study.
  void search(const StudyQuery& query);
  const std::vector<StudyRow>& studies() const { return studies_; }
  const std::vector<PatientGroup>& patients() const { return patients_; }
  int studyCount() const { return db_->studyCount(); }

  std::vector<SeriesEntry> series(const std::string& studyUid) const;
  // The same patient's earlier studies, likeliest comparison first (StudyDb::priors).
  std::vector<StudyRow> priors(const std::string& studyUid) const;

  // What File → Open would be given for the series: a folder and the series to load from it.
  // Throws Error (Input) when the series is gone or none of its files is left.
  std::pair<std::string, LoadOptions> openSeries(const std::string& seriesUid);

  // Remove from the database (and its store's copies); the user's files stay. The last
  // search is run again. Return the instances removed.
  int deleteStudy(const std::string& studyUid);
  int deleteSeries(const std::string& seriesUid);

  // Imports PATHS in the background (events: importProgress, then imported or importFailed),
  // then runs the last search again. COPY: into the database's store (else referenced).
  void importPaths(std::vector<std::string> paths, bool copy = false);
  bool importing() const { return importing_; }
  void cancelImport() { importTask_.cancel(); }
  void waitForImport() { importTask_.wait(); }

  // A PACS retrieval (PacsBrowserEvents::retrieved) copied into the database, the cache
  // evicting what it likes: the same path as `voxray-cli pacs get --db`.
  ImportReport storeRetrieved(const std::string& cachedFolder);

  // Thumbnails of STUDY's series, one at a time (events: thumbnail); replaces a previous
  // study's. Series of more than kMaxThumbnailImages images get none (decoding them all
  // for a preview takes too long).
  void makeThumbnails(const std::string& studyUid);
  void waitForThumbnails() { thumbTask_.wait(); }
  static constexpr int kMaxThumbnailImages = 300;

 private:
  void group();
  void researched();

  StudyBrowserEvents events_;
  std::unique_ptr<StudyDb> db_;
  StudyQuery lastQuery_;
  std::vector<StudyRow> studies_;
  std::vector<PatientGroup> patients_;
  std::atomic<bool> importing_{false};
  BackgroundTask importTask_;  // tasks last: their threads stop before the rest goes
  BackgroundTask thumbTask_;
};

}  // namespace voxray
#endif
