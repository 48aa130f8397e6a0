#pragma once
// littermap's own schema inside the GeoPackage (site_schema.hpp says where it ends up), versioned
// in littermap_schema_version (the GeoPackage owns PRAGMA user_version). Each migration is applied
// once, in order, in the caller's transaction; a file from a newer littermap is refused rather than
// guessed at.

#include "db/sql_connection.hpp"

namespace littermap::db {

struct MigrationResult {
  int from_version = 0;
  int to_version = 0;
  bool migrated() const { return to_version != from_version; }
};

int LatestSiteSchemaVersion();

// 0 when the version table is missing (not a littermap site, or a fresh GeoPackage).
int SiteSchemaVersion(SqlConnection& database);

// A GeoPackage gets its version table when missing, then every migration it lacks. A PostGIS
// site (its schema made from site_schema.hpp at the version it records) gets the later
// migrations, which read the same in both engines. Throws BadInputError naming the site when its
// schema is newer than this build knows.
MigrationResult MigrateSiteSchema(SqlConnection& database);

}  // namespace littermap::db
