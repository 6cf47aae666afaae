// Rows out of the study database: studies by patient, date, modality or description, one
// study, its series, a series' instances, a study's priors, and a series' files to load.
#include <string>
#include <vector>

#include "file_stamp.h"
#include "sqlite.h"
#include "study_store.h"
#include "voxray/io/error.h"
#include "voxray/studydb/study_db.h"

namespace voxray {

using studydb::fileStamp;
using studydb::Statement;

namespace {

// The study list's columns, in the order studyRow reads them (from studies s, patients p).
constexpr const char* kStudyColumns =
    "p.patient_id, p.name, p.birth_date, p.sex, s.uid, s.date, s.time, s.description, "
    "s.accession, s.study_id, s.modalities, s.series_count, s.instance_count";

StudyRow studyRow(const Statement& q) {
  StudyRow r;
  r.patient = {q.text(0), q.text(1), q.text(2), q.text(3)};
  r.study = {q.text(4), q.text(5), q.text(6), q.text(7), q.text(8), q.text(9)};
  r.modalities = q.text(10);
  r.seriesCount = int(q.integer(11));
  r.instanceCount = int(q.integer(12));
  return r;
}

// A user's pattern (* and ? wildcards) as a LIKE pattern; % _ and \ match themselves.
std::string likePattern(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '*')
      out += '%';
    else if (c == '?')
      out += '_';
    else if (c == '%' || c == '_' || c == '\\')
      out += '\\', out += c;
    else
      out += c;
  }
  return out;
}

}  // namespace

std::vector<StudyRow> StudyDb::find(const StudyQuery& query) const {
  std::string sql = std::string("SELECT ") + kStudyColumns +
                    " FROM studies s JOIN patients p ON p.id = s.patient WHERE 1";
  std::vector<std::string> values;
  auto param = [&](const std::string& v) {
    values.push_back(v);
    return "?" + std::to_string(values.size());
  };
  // Each key narrows by a set computed once (patients, series), not by a test per study
  // row: a description test per study looked at its series 10,000 times (95 ms median at
  // load 10 on 2 cores; 32 ms this way, voxray_studydb_bench).
  if (!query.patientName.empty())
    sql += " AND s.patient IN (SELECT id FROM patients WHERE name LIKE " +
           param("%" + likePattern(query.patientName) + "%") + " ESCAPE '\\')";
  if (!query.patientId.empty()) {
    // Without wildcards an exact match, which the index answers.
    const bool wild = query.patientId.find_first_of("*?") != std::string::npos;
    sql += " AND s.patient IN (SELECT id FROM patients WHERE patient_id " +
           (wild ? "LIKE " + param(likePattern(query.patientId)) + " ESCAPE '\\'"
                 : "= " + param(query.patientId)) +
           ")";
  }
  if (!query.dateFrom.empty()) sql += " AND s.date >= " + param(query.dateFrom);
  if (!query.dateTo.empty()) sql += " AND s.date <> '' AND s.date <= " + param(query.dateTo);
  if (!query.modality.empty())
    sql += " AND s.id IN (SELECT study FROM series WHERE modality = " + param(query.modality) +
           " COLLATE NOCASE)";
  if (!query.description.empty()) {
    std::string like = param("%" + likePattern(query.description) + "%");
    sql += " AND (s.description LIKE " + like +
           " ESCAPE '\\' OR s.id IN (SELECT study FROM series WHERE description LIKE " + like +
           " ESCAPE '\\'))";
  }
  sql += " ORDER BY s.date DESC, s.time DESC, s.uid";
  if (query.limit > 0) sql += " LIMIT " + std::to_string(query.limit);
  Statement q(*db_, sql.c_str());
  for (size_t i = 0; i < values.size(); ++i) q.bind(int(i + 1), values[i]);
  std::vector<StudyRow> out;
  while (q.step()) out.push_back(studyRow(q));
  return out;
}

std::vector<StudyRow> StudyDb::study(const std::string& studyUid) const {
  std::string sql = std::string("SELECT ") + kStudyColumns +
                    " FROM studies s JOIN patients p ON p.id = s.patient WHERE s.uid = ?1";
  Statement q(*db_, sql.c_str());
  q.bind(1, studyUid);
  std::vector<StudyRow> out;
  while (q.step()) out.push_back(studyRow(q));
  return out;
}

std::vector<SeriesRow> StudyDb::series(const std::string& studyUid) const {
  Statement q(*db_,
              "SELECT s.uid, x.uid, x.number, x.description, x.modality, x.body_part, "
              "x.instance_count, x.frame_count, "
              "(SELECT count(*) FROM instances i WHERE i.series = x.id AND i.state = 'missing'), "
              "(SELECT count(*) FROM instances i WHERE i.series = x.id AND i.state = 'changed') "
              "FROM series x JOIN studies s ON s.id = x.study WHERE s.uid = ?1 "
              "ORDER BY x.number, x.uid");
  q.bind(1, studyUid);
  std::vector<SeriesRow> out;
  while (q.step()) {
    SeriesRow r;
    r.studyUid = q.text(0);
    r.series.uid = q.text(1);
    r.series.number = int(q.integer(2));
    r.series.description = q.text(3);
    r.series.modality = q.text(4);
    r.series.bodyPart = q.text(5);
    r.instanceCount = int(q.integer(6));
    r.frameCount = int(q.integer(7));
    r.missing = int(q.integer(8));
    r.changed = int(q.integer(9));
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<InstanceRow> StudyDb::instances(const std::string& seriesUid) const {
  Statement q(*db_,
              "SELECT i.path, i.sop_uid, i.sop_class, i.transfer_syntax, i.position, i.number, "
              "i.frames, i.size, i.mtime, i.stored, i.state FROM instances i JOIN series x ON "
              "x.id = i.series WHERE x.uid = ?1 ORDER BY i.number, i.path");
  q.bind(1, seriesUid);
  std::vector<InstanceRow> out;
  while (q.step()) {
    InstanceRow r;
    r.seriesUid = seriesUid;
    r.instance.path = q.text(0);
    r.instance.sopInstanceUid = q.text(1);
    r.instance.sopClassUid = q.text(2);
    r.instance.transferSyntaxUid = q.text(3);
    r.instance.position = q.text(4);
    r.instance.number = int(q.integer(5));
    r.instance.frames = int(q.integer(6));
    r.instance.size = uint64_t(q.integer(7));
    r.instance.mtime = q.integer(8);
    r.instance.stored = q.integer(9) != 0;
    r.state = q.text(10);
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<StudyRow> StudyDb::priors(const std::string& studyUid) const {
  if (study(studyUid).empty())
    throw inputError("Study " + studyUid + " is not in the study database " + folder_ +
                     ": find its UID with voxray-cli db find, or import it first");
  // The same patient: the same Patient ID (names are spelled differently between
  // systems); by the patient row when the ID is empty. Earlier: an earlier date, or the same
  // date and an earlier time.
  std::string sql = std::string(
                        "WITH cur AS (SELECT s.id, s.patient, s.date, s.time, "
                        "p.patient_id FROM studies s JOIN patients p ON p.id = s.patient "
                        "WHERE s.uid = ?1), "
                        "mods AS (SELECT DISTINCT modality FROM series WHERE study = "
                        "(SELECT id FROM cur) AND modality <> ''), "
                        "parts AS (SELECT DISTINCT body_part FROM series WHERE study = "
                        "(SELECT id FROM cur) AND body_part <> '') SELECT ") +
                    kStudyColumns +
                    ", EXISTS (SELECT 1 FROM series x WHERE x.study = s.id AND x.modality IN "
                    "mods) AS same_modality, EXISTS (SELECT 1 FROM series x WHERE x.study = "
                    "s.id AND x.body_part IN parts) AS same_part "
                    "FROM studies s JOIN patients p ON p.id = s.patient, cur "
                    "WHERE s.id <> cur.id AND (CASE WHEN cur.patient_id <> '' THEN "
                    "p.patient_id = cur.patient_id ELSE s.patient = cur.patient END) "
                    "AND s.date <> '' AND (s.date < cur.date OR (s.date = cur.date AND s.time "
                    "< cur.time)) "
                    "ORDER BY same_modality DESC, same_part DESC, s.date DESC, s.time DESC";
  Statement q(*db_, sql.c_str());
  q.bind(1, studyUid);
  std::vector<StudyRow> out;
  while (q.step()) out.push_back(studyRow(q));
  return out;
}

SeriesInput StudyDb::seriesInput(const std::string& seriesUid) {
  std::vector<InstanceRow> rows = instances(seriesUid);
  if (rows.empty())
    throw inputError("Series " + seriesUid + " is not in the study database " + folder_ +
                     ": list a study's series with voxray-cli db series STUDY_UID");
  std::vector<std::string> present;
  for (const auto& r : rows) {
    uint64_t size = 0;
    int64_t mtime = 0;
    if (fileStamp(r.instance.path, size, mtime)) present.push_back(r.instance.path);
  }
  if (present.empty())
    throw inputError("Series " + seriesUid + ": none of its " + std::to_string(rows.size()) +
                     " files is where it was imported from (" + rows.front().instance.path +
                     "): import the folder again from where it is now (voxray-cli db import), "
                     "then voxray-cli db verify");
  SeriesInput input;
  input.folder =
      studydb::StudyStore(folder_ + "/store").seriesView(folder_ + "/views", seriesUid, present);
  input.series = seriesUid;
  return input;
}

}  // namespace voxray
