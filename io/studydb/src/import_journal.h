#pragma once
// imports.jsonl: every change to the database, one JSON object a line, only ever appended.
// The tables can be made again from it alone (a damaged database file, `db verify
// --rebuild`). One line per series and import: the patient, study and series fields once,
// then its instances; deletions name a study or series UID.
#include <functional>
#include <string>
#include <vector>

#include "voxray/studydb/study_records.h"

namespace voxray::studydb {

struct JournalEntry {
  enum class Op { Add, DeleteStudy, DeleteSeries } op = Op::Add;
  std::vector<InstanceRecord> records;  // Add: of one series
  std::string uid;                      // Delete*: the study or series UID
};

class ImportJournal {
 public:
  explicit ImportJournal(std::string path) : path_(std::move(path)) {}
  // Appends the records, one line per series, and flushes. Throws Error (Output).
  void appendAdd(const std::vector<InstanceRecord>& records) const;
  void appendDelete(JournalEntry::Op op, const std::string& uid) const;
  // Calls VISIT for each entry in order. A damaged line (a crash while appending leaves a
  // half line at the end) is skipped and counted in the return value.
  int replay(const std::function<void(JournalEntry&)>& visit) const;
  const std::string& path() const { return path_; }

 private:
  void append(const std::string& lines) const;
  std::string path_;
};

}  // namespace voxray::studydb
