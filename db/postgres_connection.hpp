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
};

// ? and ?N parameters (outside quotes) as PostgreSQL's $N.
std::string ToPostgresParameters(std::string_view sql);

}  // namespace littermap::db
