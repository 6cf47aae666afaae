#include "sqlite.h"

#include <sqlite3.h>

#include "voxray/io/error.h"

namespace voxray::studydb {

Sqlite::Sqlite(const std::string& path) : path_(path) {
  int rc = sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  if (rc != SQLITE_OK) {
    std::string why = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    sqlite3_close(db_);
    db_ = nullptr;
    if (rc == SQLITE_NOTADB || rc == SQLITE_CORRUPT) throw Damaged(path_, why);
    throw outputError("Cannot open the study database " + path + " (" + why +
                      "): check that its folder is writable, or choose another with --db");
  }
  // Another process (the workstation, a second CLI) may hold the write lock for a moment.
  sqlite3_busy_timeout(db_, 10000);
}

Sqlite::~Sqlite() { sqlite3_close(db_); }

void Sqlite::fail(int code, const std::string& what) const {
  std::string why = sqlite3_errmsg(db_);
  int primary = code & 0xff;
  if (primary == SQLITE_NOTADB || primary == SQLITE_CORRUPT) throw Damaged(path_, why);
  if (primary == SQLITE_FULL)
    throw outputError("The study database " + path_ + " cannot grow: its disk is full (" + why +
                      "). Free space or move the database with --db");
  throw outputError("Study database " + path_ + ": " + what + " failed (" + why + ")");
}

void Sqlite::exec(const std::string& sql) {
  char* message = nullptr;
  int rc = sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &message);
  sqlite3_free(message);
  if (rc != SQLITE_OK) fail(rc, sql.substr(0, sql.find_first_of(" (")));
}

int64_t Sqlite::lastId() const { return sqlite3_last_insert_rowid(db_); }
int Sqlite::changes() const { return sqlite3_changes(db_); }

Statement::Statement(Sqlite& db, const char* sql) : db_(db) {
  int rc = sqlite3_prepare_v2(db.handle(), sql, -1, &stmt_, nullptr);
  if (rc != SQLITE_OK) db.fail(rc, "preparing a query");
}

Statement::~Statement() { sqlite3_finalize(stmt_); }

Statement& Statement::bind(int i, const std::string& text) {
  sqlite3_bind_text(stmt_, i, text.data(), int(text.size()), SQLITE_TRANSIENT);
  return *this;
}

Statement& Statement::bind(int i, int64_t value) {
  sqlite3_bind_int64(stmt_, i, value);
  return *this;
}

bool Statement::step() {
  int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  sqlite3_reset(stmt_);
  db_.fail(rc, "a query");
}

void Statement::reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

std::string Statement::text(int column) const {
  const unsigned char* t = sqlite3_column_text(stmt_, column);
  return t ? std::string(reinterpret_cast<const char*>(t),
                         size_t(sqlite3_column_bytes(stmt_, column)))
           : std::string();
}

int64_t Statement::integer(int column) const { return sqlite3_column_int64(stmt_, column); }
bool Statement::isNull(int column) const {
  return sqlite3_column_type(stmt_, column) == SQLITE_NULL;
}

Transaction::Transaction(Sqlite& db) : db_(db) { db_.exec("BEGIN IMMEDIATE"); }

Transaction::~Transaction() {
  if (done_) return;
  char* message = nullptr;
  sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, &message);
  sqlite3_free(message);
}

void Transaction::commit() {
  db_.exec("COMMIT");
  done_ = true;
}

}  // namespace voxray::studydb
