#include "db/site_database.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/utf8.hpp"
#include "db/geopackage_schema.hpp"
#include "db/site_migrations.hpp"
#include "db/spatial_ref_sys.hpp"

namespace littermap::db {
namespace {

const FeatureTable kFeatureTables[] = {
    {"litter_items", "geom", "POINT", 0, "litter items found by the survey runs"},
    {"hotspots", "geom", "POINT", 0, "ranked local maxima of the litter density"},
    {"run_tracks", "geom", "LINESTRING", 0, "the path of each survey run"},
};

void InsertSite(SqliteDatabase& database, const SiteOptions& options, std::int32_t srs_id) {
  SqliteStatement insert = database.Prepare(
      "INSERT INTO sites (site_id, name, srs_id, epsg_code, origin_easting_m, "
      "origin_northing_m, rotation_deg) VALUES (1, ?, ?, ?, ?, ?, ?)");
  insert.Bind(1, options.name);
  insert.Bind(2, std::int64_t{srs_id});
  insert.Bind(3, std::int64_t{options.epsg_code.value_or(0)});
  insert.BindReal(4, options.origin_easting_m);
  insert.BindReal(5, options.origin_northing_m);
  insert.BindReal(6, options.rotation_deg);
  insert.Run();
}

void ValidateOptions(const std::filesystem::path& file, const SiteOptions& options) {
  if (options.name.empty()) throw UsageError("site init: --name must not be empty");
  if (std::filesystem::exists(file)) {
    throw UsageError(file.string() + ": already exists; a site database is created only once");
  }
  if (!options.epsg_code && (options.origin_easting_m != 0.0 || options.origin_northing_m != 0.0 ||
                             options.rotation_deg != 0.0)) {
    throw UsageError("site init: --origin and --rotation place the site in a CRS; give --crs too");
  }
  RequireUtf8(options.name, "site init: --name");
  RequireUtf8(file.string(), "site init: SITE");
  if (!std::isfinite(options.rotation_deg) || std::abs(options.rotation_deg) > 360.0) {
    throw UsageError("site init: --rotation must be a number of degrees from -360 to 360");
  }
  if (options.epsg_code) {
    CheckSiteOrigin(*options.epsg_code, options.origin_easting_m, options.origin_northing_m);
  }
}

}  // namespace

SiteDatabase::SiteDatabase(const std::filesystem::path& file, SqliteDatabase::Mode mode)
    : database_(file, mode) {}

void SiteDatabase::Configure() {
  database_.Execute("PRAGMA foreign_keys = ON");
  database_.Execute("PRAGMA journal_mode = WAL");
}

SiteDatabase SiteDatabase::Create(const std::filesystem::path& file, const SiteOptions& options) {
  ValidateOptions(file, options);
  const SpatialRefSys srs =
      options.epsg_code ? EpsgSpatialRefSys(*options.epsg_code) : LocalSpatialRefSys(options.name);
  try {
    SiteDatabase site(file, SqliteDatabase::Mode::kCreate);
    site.Configure();
    site.InTransaction([&] {
      CreateGeoPackageCore(site.database_);
      AddSpatialRefSys(site.database_, srs);
      MigrateSiteSchema(site.database_);
      for (FeatureTable table : kFeatureTables) {
        table.srs_id = srs.srs_id;
        RegisterFeatureTable(site.database_, table);
      }
      InsertSite(site.database_, options, srs.srs_id);
    });
    site.LoadSite();
    return site;
  } catch (...) {
    std::error_code ignored;
    for (const char* suffix : {"", "-wal", "-shm"}) {
      std::filesystem::remove(file.string() + suffix, ignored);
    }
    throw;
  }
}

SiteDatabase SiteDatabase::Open(const std::filesystem::path& file) { return OpenFile(file, false); }

SiteDatabase SiteDatabase::OpenReadOnly(const std::filesystem::path& file) {
  return OpenFile(file, true);
}

SiteDatabase SiteDatabase::OpenFile(const std::filesystem::path& file, bool read_only) {
  if (!std::filesystem::is_regular_file(file)) {
    throw BadInputError(file.string() +
                        ": no such site database (create one with 'littermap "
                        "site init')");
  }
  SiteDatabase site(file,
                    read_only ? SqliteDatabase::Mode::kReadOnly : SqliteDatabase::Mode::kReadWrite);
  try {
    OpenChecked(site, read_only);
  } catch (const SqliteError& e) {
    // The statements that open a site are those of every site littermap writes: one that fails
    // here found a damaged file, not a bug.
    if (e.kind() != ErrorKind::kInternal) throw;
    throw BadInputError(file.string() + ": not a usable littermap site database (" + e.what() +
                        ")");
  }
  return site;
}

void SiteDatabase::OpenChecked(SiteDatabase& site, bool read_only) {
  const std::filesystem::path& file = site.database_.file();
  CheckIsGeoPackage(site.database_);
  if (SiteSchemaVersion(site.database_) == 0 || !site.database_.HasTable("sites")) {
    throw BadInputError(file.string() +
                        ": a GeoPackage but not a littermap site database (no "
                        "littermap_schema_version table); create one with 'littermap site init'");
  }
  if (read_only) {
    site.database_.Execute("PRAGMA foreign_keys = ON");
    const int version = SiteSchemaVersion(site.database_);
    if (version != LatestSiteSchemaVersion()) {
      throw BadInputError(file.string() + ": site schema version " + std::to_string(version) +
                          ", this littermap reads version " +
                          std::to_string(LatestSiteSchemaVersion()) +
                          (version < LatestSiteSchemaVersion()
                               ? "; a command that writes the site (ingest, heatmap) upgrades it"
                               : "; it was written by a newer littermap"));
    }
  } else {
    site.Configure();
    site.InTransaction([&] { MigrateSiteSchema(site.database_); });
  }
  CheckSiteSchema(site.database_);
  site.LoadSite();
}

void SiteDatabase::LoadSite() {
  SqliteStatement query = database_.Prepare(
      "SELECT name, srs_id, epsg_code, origin_easting_m, origin_northing_m, rotation_deg, "
      "created_utc FROM sites WHERE site_id = 1");
  if (!query.Step()) throw BadInputError(database_.file().string() + ": table sites is empty");
  site_.name = query.ColumnText(0);
  site_.frame.srs_id = static_cast<std::int32_t>(query.ColumnInt64(1));
  site_.frame.epsg_code = static_cast<std::int32_t>(query.ColumnInt64(2));
  site_.frame.origin_easting_m = query.ColumnDouble(3);
  site_.frame.origin_northing_m = query.ColumnDouble(4);
  site_.frame.rotation_deg = query.ColumnDouble(5);
  site_.created_utc = query.ColumnText(6);
  site_.schema_version = SiteSchemaVersion(database_);
}

}  // namespace littermap::db
