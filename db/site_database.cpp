#include "db/site_database.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <thread>

#include "core/error.hpp"
#include "core/utf8.hpp"
#include "db/geopackage_schema.hpp"
#include "db/postgres_connection.hpp"
#include "db/site_migrations.hpp"
#include "db/site_schema.hpp"
#include "db/spatial_ref_sys.hpp"
#include "db/sqlite_connection.hpp"

namespace littermap::db {
namespace {

const FeatureTable kFeatureTables[] = {
    {"litter_items", "geom", "POINT", 0, "litter items found by the survey runs"},
    {"hotspots", "geom", "POINT", 0, "ranked local maxima of the litter density"},
    {"run_tracks", "geom", "LINESTRING", 0, "the path of each survey run"},
};

void InsertSite(SqlConnection& database, const SiteOptions& options, std::int32_t srs_id) {
  const auto insert = database.Prepare(
      "INSERT INTO sites (site_id, name, srs_id, epsg_code, origin_easting_m, "
      "origin_northing_m, rotation_deg) VALUES (1, ?, ?, ?, ?, ?, ?)");
  insert->Bind(1, options.name);
  insert->Bind(2, std::int64_t{srs_id});
  insert->Bind(3, std::int64_t{options.epsg_code.value_or(0)});
  insert->BindReal(4, options.origin_easting_m);
  insert->BindReal(5, options.origin_northing_m);
  insert->BindReal(6, options.rotation_deg);
  insert->Run();
}

void ValidateOptions(const std::string& where, const SiteOptions& options) {
  if (options.name.empty()) throw UsageError("site init: --name must not be empty");
  if (!options.epsg_code && (options.origin_easting_m != 0.0 || options.origin_northing_m != 0.0 ||
                             options.rotation_deg != 0.0)) {
    throw UsageError("site init: --origin and --rotation place the site in a CRS; give --crs too");
  }
  RequireUtf8(options.name, "site init: --name");
  RequireUtf8(where, "site init: SITE");
  if (!std::isfinite(options.rotation_deg) || std::abs(options.rotation_deg) > 360.0) {
    throw UsageError("site init: --rotation must be a number of degrees from -360 to 360");
  }
  if (options.epsg_code) {
    CheckSiteOrigin(*options.epsg_code, options.origin_easting_m, options.origin_northing_m);
  }
}

}  // namespace

SiteDatabase::SiteDatabase(std::unique_ptr<SqlConnection> connection)
    : connection_(std::move(connection)) {}
SiteDatabase::SiteDatabase(SiteDatabase&&) noexcept = default;
SiteDatabase::~SiteDatabase() = default;

SqliteDatabase& SiteDatabase::sqlite() {
  auto* sqlite = dynamic_cast<SqliteConnection*>(connection_.get());
  if (sqlite == nullptr) throw InternalError(name() + ": not a GeoPackage site");
  return sqlite->database();
}

void SiteDatabase::RollbackQuietly() noexcept {
  try {
    connection_->Rollback();
  } catch (...) {  // NOLINT(bugprone-empty-catch): the body's exception is the one to report;
  }                // a connection that cannot roll back has lost the transaction already
}

// Up to 10 ms x 2^attempt (at most a second), at random: writers that conflicted once do not
// meet again at the same moment.
void SiteDatabase::PauseAfterConflict(int attempt) {
  thread_local std::minstd_rand random(std::random_device{}());
  const int most_ms = std::min(1000, 10 << std::min(attempt, 7));
  std::this_thread::sleep_for(
      std::chrono::milliseconds(std::uniform_int_distribution<int>(0, most_ms)(random)));
}

void SiteDatabase::ConfigureGeoPackage() {
  connection_->Execute("PRAGMA foreign_keys = ON");
  connection_->Execute("PRAGMA journal_mode = WAL");
}

SiteDatabase SiteDatabase::Create(const SiteLocator& where, const SiteOptions& options) {
  ValidateOptions(where.display, options);
  return where.postgres() ? CreatePostgres(where, options) : CreateGeoPackage(where.file, options);
}

SiteDatabase SiteDatabase::CreateGeoPackage(const std::filesystem::path& file,
                                            const SiteOptions& options) {
  if (std::filesystem::exists(file)) {
    throw UsageError(file.string() + ": already exists; a site database is created only once");
  }
  const SpatialRefSys srs =
      options.epsg_code ? EpsgSpatialRefSys(*options.epsg_code) : LocalSpatialRefSys(options.name);
  try {
    SiteDatabase site(std::make_unique<SqliteConnection>(file, SqliteDatabase::Mode::kCreate));
    SqliteDatabase& database = site.sqlite();
    site.ConfigureGeoPackage();
    site.InTransaction([&] {
      CreateGeoPackageCore(database);
      AddSpatialRefSys(database, srs);
      MigrateSiteSchema(site.sql());
      for (FeatureTable table : kFeatureTables) {
        table.srs_id = srs.srs_id;
        RegisterFeatureTable(database, table);
      }
      InsertSite(site.sql(), options, srs.srs_id);
    });
    site.LoadSite();
    return site;
  } catch (...) {
    Remove(file);
    throw;
  }
}

SiteDatabase SiteDatabase::CreatePostgres(const SiteLocator& where, const SiteOptions& options) {
  if (options.epsg_code) EpsgSpatialRefSys(*options.epsg_code);  // throws for an unusable CRS
  auto connection =
      std::make_unique<PostgresConnection>(where.conninfo, where.schema, where.display);
  PostgresConnection& postgres = *connection;
  SiteDatabase site(std::move(connection));
  // PostGIS lives in public, as Debian's packages and QGIS expect; the site in its own schema.
  try {
    postgres.Execute("CREATE EXTENSION IF NOT EXISTS postgis SCHEMA public");
  } catch (const PostgresError& e) {
    throw EnvironmentError(where.display +
                           ": PostGIS is not installed in this database and "
                           "this login may not install it (" +
                           e.what() + ")");
  }
  site.InTransaction([&] {
    if (postgres.HasTable("sites")) {
      throw UsageError(where.display + ": already exists; a site database is created only once");
    }
    postgres.Execute("CREATE SCHEMA IF NOT EXISTS " + postgres.QuotedSchema());
    postgres.Execute(PostgresSiteSchemaSql(options.epsg_code.value_or(0)));
    const auto record = postgres.Prepare(
        "INSERT INTO littermap_schema_version (version, description) VALUES (?, ?)");
    record->Bind(1, std::int64_t{LatestSiteSchemaVersion()});
    record->Bind(2, "created at this version");
    record->Run();
    InsertSite(postgres, options, options.epsg_code.value_or(0));
  });
  site.LoadSite();
  return site;
}

bool SiteDatabase::Exists(const SiteLocator& where) {
  if (!where.postgres()) return std::filesystem::exists(where.file);
  return PostgresConnection(where.conninfo, where.schema, where.display).HasTable("sites");
}

void SiteDatabase::Remove(const SiteLocator& where) {
  if (!where.postgres()) {
    std::error_code ignored;
    for (const char* suffix : {"", "-wal", "-shm"}) {
      std::filesystem::remove(where.file.string() + suffix, ignored);
    }
    return;
  }
  PostgresConnection connection(where.conninfo, where.schema, where.display);
  connection.Execute("DROP SCHEMA IF EXISTS " + connection.QuotedSchema() + " CASCADE");
}

SiteDatabase SiteDatabase::Open(const SiteLocator& where) {
  return where.postgres() ? OpenPostgres(where, false) : OpenGeoPackage(where.file, false);
}

SiteDatabase SiteDatabase::OpenReadOnly(const SiteLocator& where) {
  return where.postgres() ? OpenPostgres(where, true) : OpenGeoPackage(where.file, true);
}

namespace {

// The site's schema version against this build's, for a site that may not be migrated here.
void RequireLatestVersion(const std::string& name, int version, const char* how_to_upgrade) {
  if (version == LatestSiteSchemaVersion()) return;
  throw BadInputError(
      name + ": site schema version " + std::to_string(version) +
      ", this littermap reads version " + std::to_string(LatestSiteSchemaVersion()) +
      (version < LatestSiteSchemaVersion() ? how_to_upgrade
                                           : "; it was written by a newer littermap"));
}

}  // namespace

SiteDatabase SiteDatabase::OpenGeoPackage(const std::filesystem::path& file, bool read_only) {
  if (!std::filesystem::is_regular_file(file)) {
    throw BadInputError(file.string() +
                        ": no such site database (create one with 'littermap "
                        "site init')");
  }
  SiteDatabase site(std::make_unique<SqliteConnection>(
      file, read_only ? SqliteDatabase::Mode::kReadOnly : SqliteDatabase::Mode::kReadWrite));
  SqliteDatabase& database = site.sqlite();
  try {
    CheckIsGeoPackage(database);
    if (SiteSchemaVersion(site.sql()) == 0 || !database.HasTable("sites")) {
      throw BadInputError(file.string() +
                          ": a GeoPackage but not a littermap site database (no "
                          "littermap_schema_version table); create one with 'littermap site "
                          "init'");
    }
    if (read_only) {
      database.Execute("PRAGMA foreign_keys = ON");
      RequireLatestVersion(file.string(), SiteSchemaVersion(site.sql()),
                           "; a command that writes the site (ingest, heatmap) upgrades it");
    } else {
      site.ConfigureGeoPackage();
      site.InTransaction([&] { MigrateSiteSchema(site.sql()); });
    }
    CheckSiteSchema(site.sql());
    site.LoadSite();
  } catch (const SqliteError& e) {
    // The statements that open a site are those of every site littermap writes: one that fails
    // here found a damaged file, not a bug.
    if (e.kind() != ErrorKind::kInternal) throw;
    throw BadInputError(file.string() + ": not a usable littermap site database (" + e.what() +
                        ")");
  }
  return site;
}

SiteDatabase SiteDatabase::OpenPostgres(const SiteLocator& where, bool read_only) {
  SiteDatabase site(
      std::make_unique<PostgresConnection>(where.conninfo, where.schema, where.display));
  SqlConnection& connection = site.sql();
  if (!connection.HasTable("sites") || !connection.HasTable("littermap_schema_version")) {
    throw BadInputError(where.display + ": no such site (create it with 'littermap site init')");
  }
  if (read_only) {
    connection.Execute("SET default_transaction_read_only = on");
    RequireLatestVersion(where.display, SiteSchemaVersion(connection),
                         "; a command that writes the site (ingest, heatmap) upgrades it");
  } else {
    site.InTransaction([&] { MigrateSiteSchema(connection); });
  }
  CheckSiteSchema(connection);
  site.LoadSite();
  return site;
}

void SiteDatabase::LoadSite() {
  const auto query = connection_->Prepare(
      "SELECT name, srs_id, epsg_code, origin_easting_m, origin_northing_m, rotation_deg, "
      "created_utc FROM sites WHERE site_id = 1");
  if (!query->Step()) throw BadInputError(name() + ": table sites is empty");
  site_.name = query->ColumnText(0);
  site_.frame.srs_id = static_cast<std::int32_t>(query->ColumnInt64(1));
  site_.frame.epsg_code = static_cast<std::int32_t>(query->ColumnInt64(2));
  site_.frame.origin_easting_m = query->ColumnDouble(3);
  site_.frame.origin_northing_m = query->ColumnDouble(4);
  site_.frame.rotation_deg = query->ColumnDouble(5);
  site_.created_utc = query->ColumnText(6);
  site_.schema_version = SiteSchemaVersion(*connection_);
}

std::string SiteDatabase::GeometryParameter(int index) const {
  const std::string parameter = "?" + std::to_string(index);
  if (engine() == SqlEngine::kSqlite) return parameter;
  return "ST_GeomFromWKB(" + parameter + ", " + std::to_string(site_.frame.epsg_code) + ")";
}

std::string SiteDatabase::GeometryColumn(const char* column) const {
  if (engine() == SqlEngine::kSqlite) return column;
  return std::string("ST_AsBinary(") + column + ")";
}

std::vector<std::uint8_t> SiteDatabase::GeometryBytes(WkbType type,
                                                      std::span<const PointXY> crs_points) const {
  if (engine() == SqlEngine::kPostgres) return EncodeWkb(type, crs_points);
  if (type == WkbType::kPoint) return EncodePoint(crs_points.front(), site_.frame.srs_id);
  return EncodeLineString(crs_points, site_.frame.srs_id);
}

GeometryBlob SiteDatabase::ReadGeometry(std::span<const std::uint8_t> bytes,
                                        const std::string& where) const {
  return engine() == SqlEngine::kSqlite ? DecodeGeometry(bytes, where) : DecodeWkb(bytes, where);
}

void SiteDatabase::ExtendLayerExtent(const std::string& table, const Envelope& crs_envelope) {
  // PostGIS layers have no stored extent: QGIS asks the spatial index.
  if (engine() == SqlEngine::kSqlite) ExtendContentsBounds(sqlite(), table, crs_envelope);
}

}  // namespace littermap::db
