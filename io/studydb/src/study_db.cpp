// The study database opened: its folder, its SQLite tables (made when new) and their counts.
// The rest of StudyDb is in study_db_import.cpp (files in), study_db_search.cpp (rows out),
// study_db_delete.cpp (rows and stored files removed) and study_db_repair.cpp (verify, rebuild).
#include "voxray/studydb/study_db.h"

#include <cstdlib>
#include <filesystem>

#include "import_journal.h"
#include "sqlite.h"
#include "voxray/io/error.h"

namespace fs = std::filesystem;

namespace voxray {

using studydb::Damaged;
using studydb::Statement;

std::string defaultStudyDbFolder() {
  if (const char* dir = std::getenv("VOXRAY_STUDY_DB"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg)
    return std::string(xdg) + "/voxray/studies";
  const char* home = std::getenv("HOME");
  return std::string(home ? home : ".") + "/.local/share/voxray/studies";
}

namespace {

constexpr const char* kSchema = R"(
CREATE TABLE IF NOT EXISTS patients(
  id INTEGER PRIMARY KEY, patient_id TEXT NOT NULL, name TEXT NOT NULL,
  birth_date TEXT NOT NULL, sex TEXT NOT NULL, UNIQUE(patient_id, name, birth_date));
CREATE TABLE IF NOT EXISTS studies(
  id INTEGER PRIMARY KEY, uid TEXT NOT NULL UNIQUE,
  patient INTEGER NOT NULL REFERENCES patients(id),
  date TEXT NOT NULL, time TEXT NOT NULL, description TEXT NOT NULL, accession TEXT NOT NULL,
  study_id TEXT NOT NULL, modalities TEXT NOT NULL DEFAULT '',
  series_count INTEGER NOT NULL DEFAULT 0, instance_count INTEGER NOT NULL DEFAULT 0);
CREATE TABLE IF NOT EXISTS series(
  id INTEGER PRIMARY KEY, uid TEXT NOT NULL UNIQUE,
  study INTEGER NOT NULL REFERENCES studies(id) ON DELETE CASCADE,
  number INTEGER NOT NULL, description TEXT NOT NULL, modality TEXT NOT NULL,
  body_part TEXT NOT NULL, instance_count INTEGER NOT NULL DEFAULT 0,
  frame_count INTEGER NOT NULL DEFAULT 0);
CREATE TABLE IF NOT EXISTS instances(
  id INTEGER PRIMARY KEY, series INTEGER NOT NULL REFERENCES series(id) ON DELETE CASCADE,
  path TEXT NOT NULL UNIQUE, sop_uid TEXT NOT NULL, sop_class TEXT NOT NULL,
  number INTEGER NOT NULL, position TEXT NOT NULL, frames INTEGER NOT NULL,
  transfer_syntax TEXT NOT NULL, size INTEGER NOT NULL, mtime INTEGER NOT NULL,
  stored INTEGER NOT NULL, state TEXT NOT NULL DEFAULT 'ok');
CREATE INDEX IF NOT EXISTS patients_name ON patients(name COLLATE NOCASE);
CREATE INDEX IF NOT EXISTS patients_id ON patients(patient_id);
CREATE INDEX IF NOT EXISTS studies_patient ON studies(patient);
CREATE INDEX IF NOT EXISTS studies_date ON studies(date, time);
CREATE INDEX IF NOT EXISTS series_study ON series(study);
CREATE INDEX IF NOT EXISTS series_modality ON series(modality COLLATE NOCASE, study);
CREATE INDEX IF NOT EXISTS instances_series ON instances(series, number);
CREATE INDEX IF NOT EXISTS instances_sop ON instances(sop_uid);
)";

}  // namespace

StudyDb::StudyDb(std::string folder) : folder_(fs::absolute(folder).lexically_normal().string()) {
  while (folder_.size() > 1 && folder_.back() == '/') folder_.pop_back();
  std::error_code ec;
  fs::create_directories(folder_, ec);
  if (ec || !fs::is_directory(folder_))
    throw outputError("Cannot create the study database folder " + folder_ + " (" +
                      (ec ? ec.message() : "not a folder") +
                      "): choose a writable folder with --db or VOXRAY_STUDY_DB");
  try {
    openTables();
  } catch (const Damaged&) {
    rebuild();
    rebuiltOnOpen_ = true;
  }
}

StudyDb::~StudyDb() = default;

void StudyDb::openTables() {
  db_.reset();
  db_ = std::make_unique<studydb::Sqlite>(folder_ + "/studies.sqlite");
  // WAL: the browser reads while an import writes. NORMAL: a power cut may lose the last
  // import's commit, never the file's consistency, and the journal has it anyway.
  db_->exec("PRAGMA journal_mode=WAL");
  db_->exec("PRAGMA synchronous=NORMAL");
  db_->exec("PRAGMA foreign_keys=ON");
  db_->exec(kSchema);
}

int StudyDb::studyCount() const {
  Statement q(*db_, "SELECT count(*) FROM studies");
  return q.step() ? int(q.integer(0)) : 0;
}

int StudyDb::instanceCount() const {
  Statement q(*db_, "SELECT count(*) FROM instances");
  return q.step() ? int(q.integer(0)) : 0;
}

}  // namespace voxray
