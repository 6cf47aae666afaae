#pragma once
// A thin RAII layer over SQLite's C API: one connection, prepared statements with bound
// values, errors as voxray::Error naming the database file and what to do.
#include <cstdint>
#include <string>

#include "voxray/io/error.h"

struct sqlite3;
struct sqlite3_stmt;

namespace voxray::studydb {

// SQLite said the file is not a database or is damaged. StudyDb rebuilds it from the
// journal when it opens; a query that finds damage later ends with this message.
struct Damaged : Error {
  Damaged(const std::string& path, const std::string& detail)
      : Error(Kind::Output, "The study database " + path + " is damaged (" + detail +
                                "): voxray-cli db verify --rebuild makes it again from its "
                                "journal") {}
};

class Sqlite {
 public:
  explicit Sqlite(const std::string& path);  // throws Error (Output), or Damaged
  ~Sqlite();
  Sqlite(const Sqlite&) = delete;
  Sqlite& operator=(const Sqlite&) = delete;

  void exec(const std::string& sql);
  int64_t lastId() const;
  int changes() const;
  sqlite3* handle() const { return db_; }
  const std::string& path() const { return path_; }
  // Throws Damaged for a damaged file, else Error (Output) with WHAT and SQLite's message.
  [[noreturn]] void fail(int code, const std::string& what) const;

 private:
  sqlite3* db_ = nullptr;
  std::string path_;
};

class Statement {
 public:
  Statement(Sqlite& db, const char* sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int i, const std::string& text);
  Statement& bind(int i, int64_t value);
  Statement& bind(int i, int value) { return bind(i, int64_t(value)); }
  // True while there is a row; false when done. Throws on error.
  bool step();
  void run() { step(), reset(); }  // executes a statement that returns no row
  void reset();

  std::string text(int column) const;
  int64_t integer(int column) const;
  bool isNull(int column) const;

 private:
  Sqlite& db_;
  sqlite3_stmt* stmt_ = nullptr;
};

// BEGIN IMMEDIATE .. COMMIT; rolled back when left by an exception.
class Transaction {
 public:
  explicit Transaction(Sqlite& db);
  ~Transaction();
  void commit();

 private:
  Sqlite& db_;
  bool done_ = false;
};

}  // namespace voxray::studydb
