#pragma once
// The local study database (issue 37): patients, studies, series and instances in SQLite
// (Debian's libsqlite3: one file, WAL, indexed search; DCMTK's own index (dcmqrdb) keeps a
// fixed-size flat file with no search beyond what a C-FIND asks and no way to rebuild it).
// Files are referenced where they are (never copied, never written to) or, for PACS
// retrievals and on request, copied into the database's store. Every change is also
// appended to imports.jsonl, from which the tables are rebuilt when the database file is
// damaged or on request. The database lives in the user's data folder, never in a folder
// it scans.
#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "voxray/studydb/study_records.h"

namespace voxray {

namespace studydb {
class Sqlite;
}

// $VOXRAY_STUDY_DB, else $XDG_DATA_HOME/voxray/studies, else ~/.local/share/voxray/studies.
std::string defaultStudyDbFolder();

struct ImportOptions {
  bool copy = false;  // copy the files into the store (else reference them in place)
  // Progress: files done of files found. May be empty.
  std::function<void(int done, int total)> progress;
  const std::atomic<bool>* cancel = nullptr;
};

// What loadVolume needs to open one series of the database: a folder of links to its files
// (under the database's folder) and the series to pick in it.
struct SeriesInput {
  std::string folder;
  std::string series;  // its Series Instance UID
};

class StudyDb {
 public:
  // Opens FOLDER's database, making it when there is none. A damaged database file is
  // rebuilt from the journal (rebuiltOnOpen() then says so). Throws Error (Output) when
  // FOLDER cannot be made or written.
  explicit StudyDb(std::string folder = defaultStudyDbFolder());
  ~StudyDb();
  StudyDb(const StudyDb&) = delete;
  StudyDb& operator=(const StudyDb&) = delete;

  const std::string& folder() const { return folder_; }
  bool rebuiltOnOpen() const { return rebuiltOnOpen_; }

  // Imports every DICOM file under PATHS (folders searched recursively, files, DICOMDIRs).
  // Headers only: parsing stops before the pixel data. Files that are not DICOM or hold no
  // instance are listed as skipped with the reason. Throws Error (Input) when a path does
  // not exist.
  ImportReport import(const std::vector<std::string>& paths, const ImportOptions& options = {});
  // Imports records already read (a PACS retrieval's files, the benchmark's rows).
  ImportReport importRecords(std::vector<InstanceRecord> records, bool copy);

  std::vector<StudyRow> find(const StudyQuery& query) const;
  std::vector<StudyRow> study(const std::string& studyUid) const;  // 0 or 1 row
  std::vector<SeriesRow> series(const std::string& studyUid) const;
  std::vector<InstanceRow> instances(const std::string& seriesUid) const;
  // The same patient's earlier studies: those sharing a modality and body part with STUDY
  // first, then a modality, then the others; newest first within each. Throws Error (Input)
  // when STUDY is not in the database.
  std::vector<StudyRow> priors(const std::string& studyUid) const;

  // Removes a study or a series from the database, and the files it copied into its store
  // (files referenced in place stay). Returns the instances removed; 0 when none matched.
  int deleteStudy(const std::string& studyUid);
  int deleteSeries(const std::string& seriesUid);

  // Checks every instance's file (there, same size and time) and records what it found.
  VerifyReport verify();
  // Makes the tables again from the journal (all of it, in order).
  void rebuild();

  // The series as an input loadVolume opens (a fresh folder of links under the database).
  // Throws Error (Input) when the series is not in the database or none of its files is left.
  SeriesInput seriesInput(const std::string& seriesUid);

  // Counts, for tests and the CLI's summary.
  int studyCount() const;
  int instanceCount() const;

 private:
  void openTables();
  void applyRecords(std::vector<InstanceRecord>& records, ImportReport& report, bool journal);
  void refreshCounts(const std::vector<std::string>& studyUids);
  int removeRows(const std::string& column, const std::string& uid, bool journal);

  std::string folder_;
  std::unique_ptr<studydb::Sqlite> db_;
  bool rebuiltOnOpen_ = false;
};

}  // namespace voxray
