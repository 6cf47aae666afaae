#pragma once
// The rows of the local study database as its users see them: what a study list shows, per
// patient, study, series and instance. Patient fields are for display to the user who asked:
// never log them or put them in messages or file names.
#include <cstdint>
#include <string>
#include <vector>

namespace voxray {

struct PatientFields {
  std::string patientId, name, birthDate, sex;
};

struct StudyFields {
  std::string uid, date, time, description, accession, studyId;
};

struct SeriesFields {
  std::string uid, description, modality, bodyPart;
  int number = 0;
};

struct InstanceFields {
  std::string path;  // absolute: in place (linked) or in the database's store (copied)
  std::string sopInstanceUid, sopClassUid, transferSyntaxUid;
  std::string position;  // ImagePositionPatient as stored ("x\y\z"), empty when absent
  int number = 0;        // InstanceNumber
  int frames = 1;        // NumberOfFrames
  uint64_t size = 0;     // bytes, with mtime: how verify tells a changed file
  int64_t mtime = 0;     // nanoseconds since the epoch
  bool stored = false;   // copied into the database's store (the database owns the file)
};

// Everything one DICOM file contributes: the import's unit, and one row of a search result.
struct InstanceRecord {
  PatientFields patient;
  StudyFields study;
  SeriesFields series;
  InstanceFields instance;
};

struct StudyRow {
  PatientFields patient;
  StudyFields study;
  std::string modalities;  // of its series, sorted, "CT\MR"
  int seriesCount = 0, instanceCount = 0;
};

struct SeriesRow {
  std::string studyUid;
  SeriesFields series;
  int instanceCount = 0, frameCount = 0;
  int missing = 0, changed = 0;  // instances verify found gone or altered
};

struct InstanceRow {
  std::string seriesUid;
  InstanceFields instance;
  std::string state;  // "ok", "missing", "changed" (as the last verify found it)
};

// A search: every field given must match; empty fields match everything.
struct StudyQuery {
  std::string patientName;       // wildcards * and ?, case-insensitive; matches any part of a name
  std::string patientId;         // exact, or with wildcards * ?
  std::string dateFrom, dateTo;  // YYYYMMDD, inclusive; either may be empty
  std::string modality;          // a study with at least one series of it
  std::string description;       // a part of the study or a series description
  int limit = 0;                 // 0: all
};

struct SkippedFile {
  std::string path;
  std::string reason;  // what the file is or what is wrong with it; no patient data
};

struct ImportReport {
  int filesScanned = 0;
  int added = 0;      // new instances
  int updated = 0;    // files already in the database, read again
  int unchanged = 0;  // files already in the database with the same size and time
  std::vector<SkippedFile> skipped;
  int notDicom = 0;                   // of skipped: not DICOM at all
  std::vector<std::string> warnings;  // duplicate SOP Instance UIDs, ...; no patient data
  std::vector<std::string> studyUids, seriesUids;  // touched by this import
};

struct VerifyReport {
  int checked = 0, ok = 0;
  std::vector<std::string> missing, changed;  // paths
  bool rebuilt = false;                       // the tables were made again from the journal
};

}  // namespace voxray
