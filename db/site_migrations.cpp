#include "db/site_migrations.hpp"

#include <string>
#include <vector>

#include "core/error.hpp"

namespace littermap::db {
namespace {

struct Migration {
  int version;
  const char* description;
  const char* sql;
  // Whether PostGIS sites made before it need it too (those start at version 4, the first
  // version a PostGIS site could have, so the statement must read the same in both engines).
  bool postgres = false;
};

// Version 1: the site, its runs and what they saw. Feature tables keep their geometry in the
// site CRS (geom) and the robot's site-frame coordinates in plain columns, so neither needs a
// transform to read back.
constexpr const char* kVersion1 = R"sql(
CREATE TABLE sites (
  site_id INTEGER PRIMARY KEY CHECK (site_id = 1),
  name TEXT NOT NULL,
  srs_id INTEGER NOT NULL REFERENCES gpkg_spatial_ref_sys(srs_id),
  epsg_code INTEGER NOT NULL,
  origin_easting_m REAL NOT NULL,
  origin_northing_m REAL NOT NULL,
  rotation_deg REAL NOT NULL,
  created_utc TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now'))
);
CREATE TABLE runs (
  run_id INTEGER PRIMARY KEY AUTOINCREMENT,
  site_id INTEGER NOT NULL REFERENCES sites(site_id),
  name TEXT NOT NULL,
  source_digest TEXT NOT NULL UNIQUE,
  start_time_s REAL,
  end_time_s REAL,
  length_m REAL,
  site_from_run_x_m REAL NOT NULL DEFAULT 0,
  site_from_run_y_m REAL NOT NULL DEFAULT 0,
  site_from_run_yaw_rad REAL NOT NULL DEFAULT 0,
  registration_quality REAL,
  ingested_utc TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now'))
);
CREATE TABLE run_tracks (
  fid INTEGER PRIMARY KEY AUTOINCREMENT,
  geom LINESTRING NOT NULL,
  run_id INTEGER NOT NULL UNIQUE REFERENCES runs(run_id) ON DELETE CASCADE,
  pose_count INTEGER NOT NULL,
  length_m REAL NOT NULL
);
CREATE TABLE litter_items (
  fid INTEGER PRIMARY KEY AUTOINCREMENT,
  geom POINT NOT NULL,
  class TEXT NOT NULL,
  site_x_m REAL NOT NULL,
  site_y_m REAL NOT NULL,
  z_m REAL,
  size_m REAL,
  confidence REAL,
  first_run_id INTEGER NOT NULL REFERENCES runs(run_id),
  last_run_id INTEGER NOT NULL REFERENCES runs(run_id),
  times_seen INTEGER NOT NULL DEFAULT 1
);
CREATE INDEX litter_items_first_run ON litter_items(first_run_id);
CREATE INDEX litter_items_last_run ON litter_items(last_run_id);
CREATE TABLE detections (
  detection_id INTEGER PRIMARY KEY AUTOINCREMENT,
  run_id INTEGER NOT NULL REFERENCES runs(run_id) ON DELETE CASCADE,
  item_fid INTEGER REFERENCES litter_items(fid) ON DELETE SET NULL,
  run_item_id TEXT NOT NULL,
  class TEXT NOT NULL,
  site_x_m REAL NOT NULL,
  site_y_m REAL NOT NULL,
  z_m REAL,
  size_m REAL,
  confidence REAL,
  UNIQUE (run_id, run_item_id)
);
CREATE INDEX detections_item ON detections(item_fid);
CREATE TABLE coverage (
  run_id INTEGER PRIMARY KEY REFERENCES runs(run_id) ON DELETE CASCADE,
  cell_size_m REAL NOT NULL,
  origin_x_m REAL NOT NULL,
  origin_y_m REAL NOT NULL,
  width INTEGER NOT NULL,
  height INTEGER NOT NULL,
  observed_area_m2 REAL NOT NULL,
  encoding TEXT NOT NULL,
  data BLOB NOT NULL
);
CREATE TABLE hotspots (
  fid INTEGER PRIMARY KEY AUTOINCREMENT,
  geom POINT NOT NULL,
  rank INTEGER NOT NULL,
  site_x_m REAL NOT NULL,
  site_y_m REAL NOT NULL,
  density_per_100m2 REAL NOT NULL,
  dominant_class TEXT,
  computed_utc TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now'))
);
)sql";

// Version 2: the site map, which later runs are registered onto: the occupancy map of the run
// that defined it (map_server grey levels, top row first) and where its frame sits in the site.
constexpr const char* kVersion2 = R"sql(
CREATE TABLE site_map (
  site_map_id INTEGER PRIMARY KEY CHECK (site_map_id = 1),
  run_id INTEGER NOT NULL REFERENCES runs(run_id),
  resolution_m REAL NOT NULL CHECK (resolution_m > 0),
  origin_x_m REAL NOT NULL,
  origin_y_m REAL NOT NULL,
  width INTEGER NOT NULL CHECK (width > 0),
  height INTEGER NOT NULL CHECK (height > 0),
  occupied_threshold REAL NOT NULL,
  site_from_map_x_m REAL NOT NULL,
  site_from_map_y_m REAL NOT NULL,
  site_from_map_yaw_rad REAL NOT NULL,
  pixels BLOB NOT NULL CHECK (length(pixels) = width * height)
);
)sql";

// Version 3: how well each run was reconstructed (reconstruct's quality.json: routines used,
// loop closures, warnings), kept verbatim so reports can show survey quality per run.
constexpr const char* kVersion3 = R"sql(
ALTER TABLE runs ADD COLUMN reconstruction_quality TEXT;
)sql";

// Version 4: GIS layers that say what they show. Each run track carries its run's name and start
// (UTC); hotspots keep one set per heatmap filter (class, from, to; '' is "any"), so a heatmap
// of one class no longer replaces the site's hotspots of all litter (the old rows, whose filter
// is not known, go; the next heatmap computes them again). The file declares
// GeoPackage 1.3 (sites made before declared 1.4, which GDAL 3.6 warns about).
constexpr const char* kVersion4 = R"sql(
ALTER TABLE run_tracks ADD COLUMN run_name TEXT;
ALTER TABLE run_tracks ADD COLUMN start_utc TEXT;
UPDATE run_tracks SET
  run_name = (SELECT name FROM runs WHERE runs.run_id = run_tracks.run_id),
  start_utc = (SELECT strftime('%Y-%m-%dT%H:%M:%SZ', start_time_s, 'unixepoch') FROM runs
               WHERE runs.run_id = run_tracks.run_id);
DELETE FROM hotspots;
ALTER TABLE hotspots ADD COLUMN filter_class TEXT NOT NULL DEFAULT '';
ALTER TABLE hotspots ADD COLUMN filter_from_utc TEXT NOT NULL DEFAULT '';
ALTER TABLE hotspots ADD COLUMN filter_to_utc TEXT NOT NULL DEFAULT '';
PRAGMA user_version = 10300;
)sql";

// Version 5: an index on the items' site coordinates, so ingest reads only the items near a
// run rather than the whole site (1,000,000 items in a city's park).
constexpr const char* kVersion5 = R"sql(
CREATE INDEX litter_items_site_x_m_site_y_m ON litter_items (site_x_m, site_y_m);
)sql";

// Version 6: hotspots of items above a confidence (heatmap --min-confidence) are kept apart from
// those of every item. Text, like the other filter columns: the value as given is the key.
constexpr const char* kVersion6 = R"sql(
ALTER TABLE hotspots ADD COLUMN filter_min_confidence TEXT NOT NULL DEFAULT '';
)sql";

const std::vector<Migration>& Migrations() {
  static const std::vector<Migration> migrations = {
      {1, "sites, runs, run_tracks, litter_items, detections, coverage, hotspots", kVersion1},
      {2, "site_map: the occupancy map later runs are registered onto", kVersion2},
      {3, "runs.reconstruction_quality: reconstruct's quality.json of each run", kVersion3},
      {4, "run_tracks.run_name/start_utc; hotspots per filter; GeoPackage 1.3", kVersion4},
      {5, "litter_items index on site_x_m, site_y_m", kVersion5, true},
      {6, "hotspots.filter_min_confidence", kVersion6, true},
  };
  return migrations;
}

}  // namespace

int LatestSiteSchemaVersion() { return Migrations().back().version; }

int SiteSchemaVersion(SqlConnection& database) {
  if (!database.HasTable("littermap_schema_version")) return 0;
  const auto query = database.Prepare("SELECT max(version) FROM littermap_schema_version");
  return query->Step() && !query->ColumnIsNull(0) ? static_cast<int>(query->ColumnInt64(0)) : 0;
}

MigrationResult MigrateSiteSchema(SqlConnection& database) {
  const bool postgres = database.engine() == SqlEngine::kPostgres;
  if (!postgres) {
    database.Execute(
        "CREATE TABLE IF NOT EXISTS littermap_schema_version (version INTEGER PRIMARY KEY, "
        "description TEXT NOT NULL, applied_utc TEXT NOT NULL "
        "DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ','now')))");
  }
  MigrationResult result;
  result.from_version = SiteSchemaVersion(database);
  result.to_version = result.from_version;
  if (result.from_version > LatestSiteSchemaVersion()) {
    throw BadInputError(database.name() + ": site schema version " +
                        std::to_string(result.from_version) + " is newer than this littermap (" +
                        std::to_string(LatestSiteSchemaVersion()) + "); update littermap");
  }
  for (const Migration& migration : Migrations()) {
    if (migration.version <= result.from_version) continue;
    if (postgres && !migration.postgres) {
      throw InternalError(database.name() + ": a PostGIS site of version " +
                          std::to_string(result.from_version) + " needs migration " +
                          std::to_string(migration.version) + ", which is GeoPackage-only");
    }
    database.Execute(migration.sql);
    const auto record = database.Prepare(
        "INSERT INTO littermap_schema_version (version, description) VALUES (?, ?)");
    record->Bind(1, std::int64_t{migration.version});
    record->Bind(2, migration.description);
    record->Run();
    result.to_version = migration.version;
  }
  return result;
}

}  // namespace littermap::db
