// The study database checked against its files (verify: missing or changed instances marked)
// and made again from its journal (rebuild: when the SQLite file is damaged).
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "file_stamp.h"
#include "import_journal.h"
#include "sqlite.h"
#include "voxray/studydb/study_db.h"

namespace fs = std::filesystem;

namespace voxray {

using studydb::fileStamp;
using studydb::ImportJournal;
using studydb::JournalEntry;
using studydb::Statement;
using studydb::Transaction;

void StudyDb::rebuild() {
  db_.reset();
  for (const char* suffix : {"", "-wal", "-shm"}) {
    std::error_code ignored;
    fs::remove(folder_ + "/studies.sqlite" + suffix, ignored);
  }
  openTables();
  ImportJournal journal(folder_ + "/imports.jsonl");
  Transaction t(*db_);
  std::set<std::string> studies;
  journal.replay([&](JournalEntry& e) {
    if (e.op == JournalEntry::Op::Add) {
      ImportReport ignored;
      applyRecords(e.records, ignored, false);
      for (const auto& r : e.records) studies.insert(r.study.uid);
    } else {
      removeRows(e.op == JournalEntry::Op::DeleteStudy ? "study" : "series", e.uid, false);
    }
  });
  refreshCounts({studies.begin(), studies.end()});
  t.commit();
}

VerifyReport StudyDb::verify() {
  VerifyReport report;
  std::vector<std::pair<int64_t, std::string>> changes;  // id, new state
  {
    Statement q(*db_, "SELECT id, path, size, mtime, state FROM instances ORDER BY path");
    while (q.step()) {
      ++report.checked;
      std::string path = q.text(1);
      uint64_t size = 0;
      int64_t mtime = 0;
      std::string state = "ok";
      if (!fileStamp(path, size, mtime)) {
        state = "missing";
        report.missing.push_back(path);
      } else if (size != uint64_t(q.integer(2)) || mtime != q.integer(3)) {
        state = "changed";
        report.changed.push_back(path);
      } else {
        ++report.ok;
      }
      if (state != q.text(4)) changes.emplace_back(q.integer(0), state);
    }
  }
  Transaction t(*db_);
  Statement set(*db_, "UPDATE instances SET state = ?2 WHERE id = ?1");
  for (const auto& [id, state] : changes) set.bind(1, id).bind(2, state).run();
  t.commit();
  return report;
}

}  // namespace voxray
