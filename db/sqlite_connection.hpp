#pragma once
// The SQLite engine of a site: a GeoPackage file (core/sqlite_database.hpp underneath).

#include <filesystem>

#include "core/sqlite_database.hpp"
#include "db/sql_connection.hpp"

namespace littermap::db {

class SqliteConnection : public SqlConnection {
 public:
  SqliteConnection(const std::filesystem::path& file, SqliteDatabase::Mode mode);

  SqlEngine engine() const override { return SqlEngine::kSqlite; }
  const std::string& name() const override { return name_; }
  void Execute(std::string_view sql) override { database_.Execute(sql); }
  std::unique_ptr<SqlStatement> Prepare(std::string_view sql) override;
  // BEGIN IMMEDIATE: the write lock is taken at once, so two writers queue (busy timeout)
  // instead of one failing when it upgrades a read lock.
  void BeginWrite() override { database_.Execute("BEGIN IMMEDIATE"); }
  // BEGIN IMMEDIATE waits for the file's write lock (the busy timeout): writers never conflict.
  bool IsConflict(const std::exception&) const override { return false; }
  void Commit() override { database_.Execute("COMMIT"); }
  void Rollback() override { database_.Execute("ROLLBACK"); }
  bool HasTable(std::string_view table) override { return database_.HasTable(table); }
  bool HasColumn(std::string_view table, std::string_view column) override {
    return database_.HasColumn(table, column);
  }

  SqliteDatabase& database() { return database_; }

 private:
  SqliteDatabase database_;
  std::string name_;
};

}  // namespace littermap::db
