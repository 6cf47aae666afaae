// Files into the study database: read each DICOM header (only what is new or changed), copy
// into the store when asked, and add the rows and the journal entry in one transaction.
#include <filesystem>
#include <map>
#include <set>

#include "dicom/file_scan.h"
#include "file_stamp.h"
#include "import_journal.h"
#include "instance_header.h"
#include "sqlite.h"
#include "study_store.h"
#include "voxray/io/error.h"
#include "voxray/studydb/study_db.h"

namespace fs = std::filesystem;

namespace voxray {

using studydb::fileStamp;
using studydb::ImportJournal;
using studydb::isUnder;
using studydb::Statement;
using studydb::Transaction;

ImportReport StudyDb::import(const std::vector<std::string>& paths, const ImportOptions& options) {
  ImportReport report;
  std::vector<std::string> files;
  for (const auto& p : paths) {
    dicom::InputFiles found = dicom::collectInputFiles(p);  // throws for a missing path
    for (auto& f : found.files) {
      std::string absolute = fs::absolute(f).lexically_normal().string();
      // The database's own files (its store, its series views) are never imported again.
      if (isUnder(absolute, folder_)) continue;
      files.push_back(std::move(absolute));
    }
  }
  report.filesScanned = int(files.size());
  Statement known(*db_, "SELECT size, mtime FROM instances WHERE path = ?1");
  std::vector<InstanceRecord> records;
  studydb::StudyStore store(folder_ + "/store");
  for (size_t i = 0; i < files.size(); ++i) {
    if (options.cancel && options.cancel->load()) throw cancelledError("Import cancelled");
    if (options.progress) options.progress(int(i), int(files.size()));
    const std::string& path = files[i];
    uint64_t size = 0;
    int64_t mtime = 0;
    if (!fileStamp(path, size, mtime)) {
      report.skipped.push_back({path, "not readable"});
      continue;
    }
    // A file already in the database, as it was: nothing to read (a second import of a
    // folder only reads what is new).
    if (!options.copy) {
      known.bind(1, path);
      bool same = known.step() && uint64_t(known.integer(0)) == size && known.integer(1) == mtime;
      known.reset();
      if (same) {
        ++report.unchanged;
        continue;
      }
    }
    InstanceRecord r;
    std::string why;
    switch (studydb::readInstanceHeader(path, r, why)) {
      case studydb::HeaderResult::NotDicom:
        ++report.notDicom;
        [[fallthrough]];
      case studydb::HeaderResult::Skipped:
        report.skipped.push_back({path, why});
        continue;
      case studydb::HeaderResult::Instance:
        break;
    }
    r.instance.path = path;
    r.instance.size = size;
    r.instance.mtime = mtime;
    if (options.copy) {
      r.instance.path = store.copyIn(path, r.study.uid, r.series.uid, r.instance.sopInstanceUid);
      fileStamp(r.instance.path, r.instance.size, r.instance.mtime);
      r.instance.stored = true;
    }
    records.push_back(std::move(r));
  }
  if (options.progress) options.progress(int(files.size()), int(files.size()));
  Transaction t(*db_);
  applyRecords(records, report, true);
  t.commit();
  return report;
}

ImportReport StudyDb::importRecords(std::vector<InstanceRecord> records, bool copy) {
  ImportReport report;
  report.filesScanned = int(records.size());
  if (copy) {
    studydb::StudyStore store(folder_ + "/store");
    for (auto& r : records) {
      r.instance.path =
          store.copyIn(r.instance.path, r.study.uid, r.series.uid, r.instance.sopInstanceUid);
      fileStamp(r.instance.path, r.instance.size, r.instance.mtime);
      r.instance.stored = true;
    }
  }
  Transaction t(*db_);
  applyRecords(records, report, true);
  t.commit();
  return report;
}

void StudyDb::applyRecords(std::vector<InstanceRecord>& records, ImportReport& report,
                           bool journal) {
  if (records.empty()) return;
  Statement patientIns(*db_,
                       "INSERT OR IGNORE INTO patients(patient_id, name, birth_date, sex) "
                       "VALUES(?1, ?2, ?3, ?4)");
  Statement patientId(*db_,
                      "SELECT id FROM patients WHERE patient_id = ?1 AND name = ?2 AND "
                      "birth_date = ?3");
  Statement studyIns(*db_,
                     "INSERT OR IGNORE INTO studies(uid, patient, date, time, description, "
                     "accession, study_id) VALUES(?1, ?2, ?3, ?4, ?5, ?6, ?7)");
  Statement studyId(*db_, "SELECT id FROM studies WHERE uid = ?1");
  Statement seriesIns(*db_,
                      "INSERT OR IGNORE INTO series(uid, study, number, description, modality, "
                      "body_part) VALUES(?1, ?2, ?3, ?4, ?5, ?6)");
  Statement seriesId(*db_, "SELECT id FROM series WHERE uid = ?1");
  // The study a file belonged to: a file replaced by another series' file leaves its old
  // study's counts to recount.
  Statement existing(*db_,
                     "SELECT s.uid FROM instances i JOIN series x ON x.id = i.series JOIN "
                     "studies s ON s.id = x.study WHERE i.path = ?1");
  Statement duplicate(*db_, "SELECT size FROM instances WHERE sop_uid = ?1 AND path <> ?2 LIMIT 1");
  Statement instanceUpsert(
      *db_,
      "INSERT INTO instances(series, path, sop_uid, sop_class, number, position, frames, "
      "transfer_syntax, size, mtime, stored, state) "
      "VALUES(?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, 'ok') "
      "ON CONFLICT(path) DO UPDATE SET series = ?1, sop_uid = ?3, sop_class = ?4, number = ?5, "
      "position = ?6, frames = ?7, transfer_syntax = ?8, size = ?9, mtime = ?10, stored = ?11, "
      "state = 'ok'");
  std::map<std::string, int64_t> patients, studies, series;
  std::set<std::string> touchedStudies, touchedSeries;
  auto idOf = [](Statement& q) {
    int64_t id = q.step() ? q.integer(0) : -1;
    q.reset();
    return id;
  };
  for (const auto& r : records) {
    std::string patientKey =
        r.patient.patientId + '\0' + r.patient.name + '\0' + r.patient.birthDate;
    auto p = patients.find(patientKey);
    if (p == patients.end()) {
      patientIns.bind(1, r.patient.patientId).bind(2, r.patient.name).bind(3, r.patient.birthDate);
      patientIns.bind(4, r.patient.sex).run();
      patientId.bind(1, r.patient.patientId).bind(2, r.patient.name).bind(3, r.patient.birthDate);
      p = patients.emplace(patientKey, idOf(patientId)).first;
    }
    auto s = studies.find(r.study.uid);
    if (s == studies.end()) {
      studyIns.bind(1, r.study.uid).bind(2, p->second).bind(3, r.study.date).bind(4, r.study.time);
      studyIns.bind(5, r.study.description)
          .bind(6, r.study.accession)
          .bind(7, r.study.studyId)
          .run();
      studyId.bind(1, r.study.uid);
      s = studies.emplace(r.study.uid, idOf(studyId)).first;
    }
    auto se = series.find(r.series.uid);
    if (se == series.end()) {
      seriesIns.bind(1, r.series.uid).bind(2, s->second).bind(3, r.series.number);
      seriesIns.bind(4, r.series.description).bind(5, r.series.modality).bind(6, r.series.bodyPart);
      seriesIns.run();
      seriesId.bind(1, r.series.uid);
      se = series.emplace(r.series.uid, idOf(seriesId)).first;
    }
    const InstanceFields& i = r.instance;
    existing.bind(1, i.path);
    bool present = existing.step();
    if (present) touchedStudies.insert(existing.text(0));
    existing.reset();
    (present ? report.updated : report.added)++;
    duplicate.bind(1, i.sopInstanceUid).bind(2, i.path);
    if (duplicate.step())
      report.warnings.push_back(
          "SOP Instance UID " + i.sopInstanceUid + " is also in another file" +
          (uint64_t(duplicate.integer(0)) != i.size ? " with different content" : "") + " (" +
          i.path + "): both are kept");
    duplicate.reset();
    instanceUpsert.bind(1, se->second).bind(2, i.path).bind(3, i.sopInstanceUid);
    instanceUpsert.bind(4, i.sopClassUid).bind(5, i.number).bind(6, i.position).bind(7, i.frames);
    instanceUpsert.bind(8, i.transferSyntaxUid).bind(9, int64_t(i.size)).bind(10, i.mtime);
    instanceUpsert.bind(11, int64_t(i.stored)).run();
    touchedStudies.insert(r.study.uid);
    touchedSeries.insert(r.series.uid);
  }
  if (journal) ImportJournal(folder_ + "/imports.jsonl").appendAdd(records);
  if (journal) refreshCounts({touchedStudies.begin(), touchedStudies.end()});
  report.studyUids.assign(touchedStudies.begin(), touchedStudies.end());
  report.seriesUids.assign(touchedSeries.begin(), touchedSeries.end());
}

void StudyDb::refreshCounts(const std::vector<std::string>& studyUids) {
  Statement seriesCounts(
      *db_,
      "UPDATE series SET instance_count = (SELECT count(*) FROM instances i WHERE i.series = "
      "series.id), frame_count = (SELECT coalesce(sum(frames), 0) FROM instances i WHERE "
      "i.series = series.id) WHERE study = (SELECT id FROM studies WHERE uid = ?1)");
  Statement studyCounts(
      *db_,
      "UPDATE studies SET series_count = (SELECT count(*) FROM series x WHERE x.study = "
      "studies.id), instance_count = (SELECT coalesce(sum(instance_count), 0) FROM series x "
      "WHERE x.study = studies.id), modalities = coalesce((SELECT group_concat(modality, '\\') "
      "FROM (SELECT DISTINCT modality FROM series x WHERE x.study = studies.id AND modality <> "
      "'' ORDER BY modality)), '') WHERE uid = ?1");
  for (const auto& uid : studyUids) {
    seriesCounts.bind(1, uid).run();
    studyCounts.bind(1, uid).run();
  }
}

}  // namespace voxray
