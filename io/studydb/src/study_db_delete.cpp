// A study or series out of the study database: its rows, a journal entry, and the files the
// database copied into its store (never the user's own).
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "file_stamp.h"
#include "import_journal.h"
#include "sqlite.h"
#include "voxray/studydb/study_db.h"

namespace fs = std::filesystem;

namespace voxray {

using studydb::ImportJournal;
using studydb::isUnder;
using studydb::JournalEntry;
using studydb::Statement;
using studydb::Transaction;

int StudyDb::removeRows(const std::string& column, const std::string& uid, bool journal) {
  const bool study = column == "study";
  std::string where = study ? "x.study = (SELECT id FROM studies WHERE uid = ?1)" : "x.uid = ?1";
  std::vector<std::string> storedFiles;
  std::set<std::string> studyUids;
  {
    std::string sql =
        "SELECT i.path, i.stored, (SELECT uid FROM studies WHERE id = x.study) "
        "FROM instances i JOIN series x ON x.id = i.series WHERE " +
        where;
    Statement q(*db_, sql.c_str());
    q.bind(1, uid);
    while (q.step()) {
      if (q.integer(1) != 0) storedFiles.push_back(q.text(0));
      studyUids.insert(q.text(2));
    }
  }
  Statement count(*db_, ("SELECT count(*) FROM instances i JOIN series x ON x.id = i.series "
                         "WHERE " +
                         where)
                            .c_str());
  count.bind(1, uid);
  int removed = count.step() ? int(count.integer(0)) : 0;
  count.reset();
  if (study) {
    Statement del(*db_, "DELETE FROM studies WHERE uid = ?1");
    del.bind(1, uid).run();
    if (db_->changes() == 0 && removed == 0) return 0;
  } else {
    Statement owner(*db_,
                    "SELECT s.uid FROM series x JOIN studies s ON s.id = x.study WHERE x.uid = ?1");
    owner.bind(1, uid);
    if (owner.step()) studyUids.insert(owner.text(0));
    Statement del(*db_, "DELETE FROM series WHERE uid = ?1");
    del.bind(1, uid).run();
    if (db_->changes() == 0) return 0;
    refreshCounts({studyUids.begin(), studyUids.end()});
    // A study left without series goes too.
    db_->exec(
        "DELETE FROM studies WHERE NOT EXISTS (SELECT 1 FROM series x WHERE x.study = "
        "studies.id)");
  }
  db_->exec("DELETE FROM patients WHERE id NOT IN (SELECT patient FROM studies)");
  if (journal) {
    ImportJournal(folder_ + "/imports.jsonl")
        .appendDelete(study ? JournalEntry::Op::DeleteStudy : JournalEntry::Op::DeleteSeries, uid);
    // Only files the database copied into its store: never the user's own.
    for (const auto& f : storedFiles)
      if (isUnder(f, folder_ + "/store")) {
        std::error_code ignored;
        fs::remove(f, ignored);
      }
  }
  return removed;
}

int StudyDb::deleteStudy(const std::string& studyUid) {
  Transaction t(*db_);
  int n = removeRows("study", studyUid, true);
  t.commit();
  return n;
}

int StudyDb::deleteSeries(const std::string& seriesUid) {
  Transaction t(*db_);
  int n = removeRows("series", seriesUid, true);
  t.commit();
  return n;
}

}  // namespace voxray
