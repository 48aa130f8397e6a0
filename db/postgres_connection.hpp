#pragma once
// The PostgreSQL engine of a site: one schema of a PostGIS database, reached through libpq.
// The connection's search_path is the site's schema, then public (where PostGIS lives), so the
// site's statements name its tables as they do in a GeoPackage.

#include <string>

#include "core/error.hpp"
#include "db/sql_connection.hpp"

struct pg_conn;

namespace littermap::db {

// A failed statement or connection; the kind follows the SQLSTATE class: the server gone, out
// of resources, refusing the login or a conflict between transactions is the environment; data
// the site's constraints refuse is bad input; anything else is a wrong statement (internal).
class PostgresError : public Error {
 public:
  PostgresError(ErrorKind kind, const std::string& message, std::string sqlstate)
      : Error(kind, message), sqlstate_(std::move(sqlstate)) {}
  const std::string& sqlstate() const { return sqlstate_; }

 private:
  std::string sqlstate_;
};

// How the writers of one site are kept from stepping on each other. The advisory lock is
// littermap's choice (bench/site_concurrency_bench measures both): an ingest reads the items
// around its run and adds to them, so two ingests of overlapping areas always conflict, and
// under SERIALIZABLE one of them redoes its whole run.
enum class PostgresWriteSerialisation {
  kAdvisoryLock,              // BEGIN, then the site's lock: writers queue
  kSerializableTransactions,  // BEGIN ISOLATION LEVEL SERIALIZABLE: conflicts abort, then retry
};

class PostgresConnection : public SqlConnection {
 public:
  // conninfo: what libpq reads (a postgresql:// URI without littermap's own parameters);
  // schema: the site's; name: for messages. Throws PostgresError (environment) when the server
  // cannot be reached or refuses the login.
  PostgresConnection(const std::string& conninfo, std::string schema, std::string name);
  ~PostgresConnection() override;
  PostgresConnection(const PostgresConnection&) = delete;
  PostgresConnection& operator=(const PostgresConnection&) = delete;

  SqlEngine engine() const override { return SqlEngine::kPostgres; }
  const std::string& name() const override { return name_; }
  void Execute(std::string_view sql) override;
  std::unique_ptr<SqlStatement> Prepare(std::string_view sql) override;
  // BEGIN, then the site's advisory lock (held to the end of the transaction): writers of one
  // site queue, writers of other sites do not wait for them.
  void BeginWrite() override;
  bool IsConflict(const std::exception& error) const override;
  void set_write_serialisation(PostgresWriteSerialisation mode) { write_serialisation_ = mode; }
  void Commit() override { Execute("COMMIT"); }
  void Rollback() override { Execute("ROLLBACK"); }
  bool HasTable(std::string_view table) override;
  bool HasColumn(std::string_view table, std::string_view column) override;

  const std::string& schema() const { return schema_; }
  // The schema quoted as an SQL identifier.
  std::string QuotedSchema() const;

 private:
  pg_conn* connection_ = nullptr;
  std::string schema_;
  std::string name_;
  PostgresWriteSerialisation write_serialisation_ = PostgresWriteSerialisation::kAdvisoryLock;
};

// ? and ?N parameters (outside quotes) as PostgreSQL's $N.
std::string ToPostgresParameters(std::string_view sql);

}  // namespace littermap::db
