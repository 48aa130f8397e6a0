#include "db/geopackage_schema.hpp"

#include <cstdio>

#include "core/error.hpp"

namespace littermap::db {
namespace {

// Table definitions as given in the specification (clauses 1.1.2.1.1, 1.1.3.1.1, 2.1.5.1.1).
constexpr const char* kCoreTablesSql = R"sql(
CREATE TABLE gpkg_spatial_ref_sys (
  srs_name TEXT NOT NULL,
  srs_id INTEGER PRIMARY KEY,
  organization TEXT NOT NULL,
  organization_coordsys_id INTEGER NOT NULL,
  definition TEXT NOT NULL,
  description TEXT
);
CREATE TABLE gpkg_contents (
  table_name TEXT NOT NULL PRIMARY KEY,
  data_type TEXT NOT NULL,
  identifier TEXT UNIQUE,
  description TEXT DEFAULT '',
  last_change DATETIME NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now')),
  min_x DOUBLE,
  min_y DOUBLE,
  max_x DOUBLE,
  max_y DOUBLE,
  srs_id INTEGER,
  CONSTRAINT fk_gc_r_srs_id FOREIGN KEY (srs_id) REFERENCES gpkg_spatial_ref_sys(srs_id)
);
CREATE TABLE gpkg_geometry_columns (
  table_name TEXT NOT NULL,
  column_name TEXT NOT NULL,
  geometry_type_name TEXT NOT NULL,
  srs_id INTEGER NOT NULL,
  z TINYINT NOT NULL,
  m TINYINT NOT NULL,
  CONSTRAINT pk_geom_cols PRIMARY KEY (table_name, column_name),
  CONSTRAINT uk_gc_table_name UNIQUE (table_name),
  CONSTRAINT fk_gc_tn FOREIGN KEY (table_name) REFERENCES gpkg_contents(table_name),
  CONSTRAINT fk_gc_srs FOREIGN KEY (srs_id) REFERENCES gpkg_spatial_ref_sys (srs_id)
);
)sql";

std::int64_t PragmaValue(SqliteDatabase& database, const char* pragma) {
  SqliteStatement query = database.Prepare(std::string("PRAGMA ") + pragma);
  return query.Step() ? query.ColumnInt64(0) : 0;
}

}  // namespace

void CreateGeoPackageCore(SqliteDatabase& database) {
  database.Execute("PRAGMA application_id = " + std::to_string(kGeoPackageApplicationId));
  database.Execute("PRAGMA user_version = " + std::to_string(kGeoPackageUserVersion));
  database.Execute(kCoreTablesSql);
  for (const SpatialRefSys& srs : RequiredSpatialRefSys()) AddSpatialRefSys(database, srs);
}

void AddSpatialRefSys(SqliteDatabase& database, const SpatialRefSys& srs) {
  SqliteStatement insert = database.Prepare(
      "INSERT OR IGNORE INTO gpkg_spatial_ref_sys (srs_name, srs_id, organization, "
      "organization_coordsys_id, definition, description) VALUES (?, ?, ?, ?, ?, ?)");
  insert.Bind(1, srs.srs_name);
  insert.Bind(2, std::int64_t{srs.srs_id});
  insert.Bind(3, srs.organization);
  insert.Bind(4, std::int64_t{srs.organization_coordsys_id});
  insert.Bind(5, srs.definition);
  insert.Bind(6, srs.description);
  insert.Run();
}

void RegisterFeatureTable(SqliteDatabase& database, const FeatureTable& table) {
  SqliteStatement contents = database.Prepare(
      "INSERT INTO gpkg_contents (table_name, data_type, identifier, description, srs_id) "
      "VALUES (?, 'features', ?, ?, ?)");
  contents.Bind(1, table.table_name);
  contents.Bind(2, table.table_name);
  contents.Bind(3, table.description);
  contents.Bind(4, std::int64_t{table.srs_id});
  contents.Run();
  SqliteStatement columns = database.Prepare(
      "INSERT INTO gpkg_geometry_columns (table_name, column_name, geometry_type_name, srs_id, "
      "z, m) VALUES (?, ?, ?, ?, 0, 0)");
  columns.Bind(1, table.table_name);
  columns.Bind(2, table.geometry_column);
  columns.Bind(3, table.geometry_type);
  columns.Bind(4, std::int64_t{table.srs_id});
  columns.Run();
}

void ExtendContentsBounds(SqliteDatabase& database, const std::string& table_name,
                          const Envelope& envelope) {
  SqliteStatement update = database.Prepare(
      "UPDATE gpkg_contents SET min_x = min(coalesce(min_x, ?1), ?1), "
      "max_x = max(coalesce(max_x, ?2), ?2), min_y = min(coalesce(min_y, ?3), ?3), "
      "max_y = max(coalesce(max_y, ?4), ?4), "
      "last_change = strftime('%Y-%m-%dT%H:%M:%fZ','now') WHERE table_name = ?5");
  update.BindReal(1, envelope.min_x);
  update.BindReal(2, envelope.max_x);
  update.BindReal(3, envelope.min_y);
  update.BindReal(4, envelope.max_y);
  update.Bind(5, table_name);
  update.Run();
}

void CheckIsGeoPackage(SqliteDatabase& database) {
  const std::string file = database.file().string();
  std::int64_t application_id = 0;
  try {
    application_id = PragmaValue(database, "application_id");
  } catch (const SqliteError& e) {
    // A file one may not write (read-only, its folder too) is the environment, not the file.
    if (e.kind() == ErrorKind::kEnvironment) throw;
    throw BadInputError(file + ": not a GeoPackage: not an SQLite database (" + e.what() + ")");
  }
  if (application_id != kGeoPackageApplicationId) {
    char text[16];
    std::snprintf(text, sizeof(text), "0x%08llX", static_cast<unsigned long long>(application_id));
    throw BadInputError(file + ": not a GeoPackage: application_id is " + text +
                        ", expected 0x47504B47 ('GPKG')");
  }
  for (const char* table : {"gpkg_spatial_ref_sys", "gpkg_contents", "gpkg_geometry_columns"}) {
    if (!database.HasTable(table)) {
      throw BadInputError(file + ": damaged GeoPackage: required table " + table + " is missing");
    }
  }
}

}  // namespace littermap::db
