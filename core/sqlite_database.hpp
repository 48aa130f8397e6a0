#pragma once
// A thin RAII layer over the SQLite C API (run bag, site database): one connection, prepared
// statements, and errors that name the database file. SQLite failures throw SqliteError (an
// InternalError); callers that know the file came from the user turn them into BadInputError.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "core/error.hpp"

struct sqlite3;
struct sqlite3_stmt;

namespace littermap {

// The kind of an SQLite result code: environment for a full disk, an I/O error, a read-only or
// unopenable file, no memory or a lock held too long; bad input for a file that is not a
// database or is damaged; internal (a wrong statement: a bug) for the rest.
ErrorKind SqliteErrorKind(int code);

class SqliteError : public Error {
 public:
  SqliteError(const std::string& message, int code)
      : Error(SqliteErrorKind(code), message), code_(code) {}
  SqliteError(const std::string& message, int code, ErrorKind kind)
      : Error(kind, message), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

class SqliteStatement {
 public:
  SqliteStatement(sqlite3* db, std::string_view sql, const std::filesystem::path& file);
  ~SqliteStatement();
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;
  SqliteStatement(SqliteStatement&& other) noexcept;
  SqliteStatement& operator=(SqliteStatement&&) = delete;

  // Parameters are 1-based, as in SQLite.
  void Bind(int index, std::int64_t value);
  void BindReal(int index, double value);
  void BindNull(int index);
  void Bind(int index, std::string_view text);
  void BindBlob(int index, std::span<const std::uint8_t> blob);

  // Steps once: true when a row is available, false when done. Throws SqliteError on failure.
  bool Step();
  // Steps a statement that returns no rows, then resets it for reuse.
  void Run();
  void Reset();

  std::int64_t ColumnInt64(int column) const;
  double ColumnDouble(int column) const;
  bool ColumnIsNull(int column) const;
  std::string ColumnText(int column) const;
  std::span<const std::uint8_t> ColumnBlob(int column) const;  // valid until the next Step

 private:
  [[noreturn]] void Fail(int code, const char* action) const;

  sqlite3* db_;
  sqlite3_stmt* statement_ = nullptr;
  std::filesystem::path file_;
};

class SqliteDatabase {
 public:
  // kReadOnly reads a database in a folder one may not write (a share, a read-only file system)
  // too: SQLite needs to create a WAL database's -shm file next to it, so when the folder is not
  // writable and no -wal file holds changes not yet in the database, the file is opened as
  // immutable (read without locks: nothing can be writing it there either).
  enum class Mode { kReadOnly, kReadWrite, kCreate };
  SqliteDatabase(const std::filesystem::path& file, Mode mode);
  ~SqliteDatabase();
  SqliteDatabase(const SqliteDatabase&) = delete;
  SqliteDatabase& operator=(const SqliteDatabase&) = delete;
  SqliteDatabase(SqliteDatabase&& other) noexcept;
  SqliteDatabase& operator=(SqliteDatabase&&) = delete;

  void Execute(std::string_view sql);
  SqliteStatement Prepare(std::string_view sql) const;
  std::int64_t LastInsertId() const;
  int Changes() const;  // rows the last INSERT, UPDATE or DELETE changed
  bool HasTable(std::string_view table) const;
  bool HasColumn(std::string_view table, std::string_view column) const;
  const std::filesystem::path& file() const { return file_; }

 private:
  sqlite3* db_ = nullptr;
  std::filesystem::path file_;
};

}  // namespace littermap
