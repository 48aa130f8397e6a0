#pragma once
// The site schema at its latest version, in terms both engines share: each table's columns in
// order, with a logical type and the constraints standard SQL writes the same way in SQLite and
// PostgreSQL. A PostGIS site is created from it; a GeoPackage reaches it through the migrations
// of site_migrations.cpp (a test holds the two equal); both are checked against it when opened.

#include <string>
#include <vector>

#include "db/sql_connection.hpp"

namespace littermap::db {

enum class ColumnType { kId, kInteger, kReal, kText, kBlob, kPoint, kLineString, kNowUtc };

struct ColumnSpec {
  const char* name;
  ColumnType type;
  const char* constraints = "";  // NOT NULL, UNIQUE, REFERENCES ..., DEFAULT ..., CHECK (...)
};

struct TableSpec {
  const char* name;
  std::vector<ColumnSpec> columns;
  const char* table_constraints = "";  // e.g. UNIQUE (run_id, run_item_id)
  // One index each, named TABLE_COLUMNS: a column (GiST for geometry) or a list "a, b".
  std::vector<const char*> indexed_columns;
};

inline bool IsGeometry(ColumnType type) {
  return type == ColumnType::kPoint || type == ColumnType::kLineString;
}

const std::vector<TableSpec>& SiteSchema();

// The PostgreSQL statements that create the schema's tables and indexes in the connection's
// schema; geometry columns carry `srid` (0: a local engineering frame).
std::string PostgresSiteSchemaSql(int srid);

// Throws BadInputError naming the site when a table or column of SiteSchema() is missing: a
// damaged site, or one another program wrote, is refused when opened rather than failing later.
void CheckSiteSchema(SqlConnection& connection);

}  // namespace littermap::db
