#pragma once
// One connection to a site's database, whichever engine holds it: an SQLite GeoPackage file or a
// schema of a PostgreSQL + PostGIS database. Statements are written once, in the SQL both
// engines read, with SQLite's parameters (? and ?N, 1-based); the PostgreSQL connection turns
// them into $N. Where the engines differ (geometry in and out, the write lock), the site asks
// its connection rather than holding two statements.

#include <cstdint>
#include <exception>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace littermap::db {

enum class SqlEngine { kSqlite, kPostgres };

class SqlStatement {
 public:
  virtual ~SqlStatement() = default;

  virtual void Bind(int index, std::int64_t value) = 0;
  virtual void BindReal(int index, double value) = 0;
  virtual void BindNull(int index) = 0;
  virtual void Bind(int index, std::string_view text) = 0;
  // The bytes must stay alive until the statement has run (SQLite binds them without a copy).
  virtual void BindBlob(int index, std::span<const std::uint8_t> blob) = 0;

  // Steps once: true when a row is available, false when done.
  virtual bool Step() = 0;
  // Runs a statement that returns no rows, then resets it for reuse (bindings stay).
  virtual void Run() = 0;
  virtual void Reset() = 0;

  virtual std::int64_t ColumnInt64(int column) const = 0;
  virtual double ColumnDouble(int column) const = 0;
  virtual bool ColumnIsNull(int column) const = 0;
  virtual std::string ColumnText(int column) const = 0;
  virtual std::span<const std::uint8_t> ColumnBlob(int column) const = 0;  // until next Step
};

class SqlConnection {
 public:
  virtual ~SqlConnection() = default;

  virtual SqlEngine engine() const = 0;
  // For messages: the file, or the database and site (never a password).
  virtual const std::string& name() const = 0;

  // Statements separated by semicolons, no parameters, no rows.
  virtual void Execute(std::string_view sql) = 0;
  virtual std::unique_ptr<SqlStatement> Prepare(std::string_view sql) = 0;
  // Starts the transaction that writes the site: the one writer at a time.
  virtual void BeginWrite() = 0;
  virtual void Commit() = 0;
  virtual void Rollback() = 0;
  // Whether `error` is the engine aborting a transaction because a concurrent one conflicted with
  // it (PostgreSQL's serialization_failure or deadlock_detected): running it again is the cure.
  virtual bool IsConflict(const std::exception& error) const = 0;

  virtual bool HasTable(std::string_view table) = 0;
  virtual bool HasColumn(std::string_view table, std::string_view column) = 0;
};

}  // namespace littermap::db
