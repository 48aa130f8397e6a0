#pragma once
// The GeoPackage core (OGC 12-128r18, version 1.4): the SQLite header fields, the required
// metadata tables and rows, feature table registration, and the check that a file is one.

#include <cstdint>
#include <string>

#include "core/sqlite_database.hpp"
#include "db/geometry_blob.hpp"
#include "db/spatial_ref_sys.hpp"

namespace littermap::db {

constexpr std::int32_t kGeoPackageApplicationId = 0x47504B47;  // "GPKG"
// 1.3.0: littermap uses nothing of 1.4, and GDAL 3.6 (Debian 12's, under its QGIS) warns on
// every file that declares a version above 1.3.
constexpr std::int32_t kGeoPackageUserVersion = 10300;

// Sets application_id and user_version and creates gpkg_spatial_ref_sys (with the required
// rows), gpkg_contents and gpkg_geometry_columns. Call inside a fresh, empty database.
void CreateGeoPackageCore(SqliteDatabase& database);

void AddSpatialRefSys(SqliteDatabase& database, const SpatialRefSys& srs);

struct FeatureTable {
  std::string table_name;
  std::string geometry_column = "geom";
  std::string geometry_type;  // "POINT", "LINESTRING"
  std::int32_t srs_id = 0;
  std::string description;
};

// Registers an existing feature table in gpkg_contents and gpkg_geometry_columns.
void RegisterFeatureTable(SqliteDatabase& database, const FeatureTable& table);

// Widens the bounding box of a table in gpkg_contents and stamps last_change.
void ExtendContentsBounds(SqliteDatabase& database, const std::string& table_name,
                          const Envelope& envelope);

// Throws BadInputError naming the file when it is not an SQLite database, its application_id
// is not 'GPKG', or a core table is missing.
void CheckIsGeoPackage(SqliteDatabase& database);

}  // namespace littermap::db
