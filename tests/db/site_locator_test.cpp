// Site addresses (a path or a PostgreSQL URI), statements for both engines, and the one schema
// description against the GeoPackage's migrations.

#include "db/site_locator.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/sqlite_database.hpp"
#include "db/postgres_connection.hpp"
#include "db/site_migrations.hpp"
#include "db/site_schema.hpp"
#include "db/sqlite_connection.hpp"

namespace littermap::db {
namespace {

TEST(SiteLocator, APathIsAGeoPackage) {
  const SiteLocator site = ParseSiteLocator("parks/north.gpkg");
  EXPECT_FALSE(site.postgres());
  EXPECT_EQ(site.file, "parks/north.gpkg");
  EXPECT_EQ(site.display, "parks/north.gpkg");
}

TEST(SiteLocator, TheSiteParameterNamesTheSchemaAndLeavesTheUri) {
  const SiteLocator site = ParseSiteLocator(
      "postgresql://robot:secret@db.city.example:5433/city?site=north_park&"
      "sslmode=require");
  ASSERT_TRUE(site.postgres());
  EXPECT_EQ(site.schema, "north_park");
  EXPECT_EQ(site.conninfo, "postgresql://robot:secret@db.city.example:5433/city?sslmode=require");
  EXPECT_EQ(site.display, "postgresql://robot@db.city.example:5433/city (site north_park)");
}

TEST(SiteLocator, ASearchPathInOptionsNamesTheSchema) {
  const SiteLocator site =
      ParseSiteLocator("postgresql://user@host/db?options=-csearch_path%3Dnorth_park");
  EXPECT_EQ(site.schema, "north_park");
  EXPECT_EQ(site.conninfo, "postgresql://user@host/db?options=-csearch_path%3Dnorth_park");
  EXPECT_EQ(ParseSiteLocator("postgres:///city?site=s1").schema, "s1");
}

TEST(SiteLocator, AUriWithoutAPlainSiteNameIsRefused) {
  try {
    ParseSiteLocator("postgresql:///city", "--site");
    FAIL() << "no site name";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--site: postgresql:///city names no site; add ?site=NAME (the schema that holds "
              "the site)");
  }
  for (const char* bad : {"North", "1park", "a-b", "x;drop", "\"q\""}) {
    EXPECT_THROW(ParseSiteLocator(std::string("postgresql:///city?site=") + bad), UsageError)
        << bad;
  }
  EXPECT_THROW(ParseSiteLocator("postgresql:///city?site=" + std::string(64, 'a')), UsageError);
  EXPECT_NO_THROW(ParseSiteLocator("postgresql:///city?site=" + std::string(63, 'a')));
}

TEST(PostgresParameters, QuestionMarksBecomeNumberedOutsideQuotes) {
  EXPECT_EQ(ToPostgresParameters("SELECT a FROM t WHERE b = ? AND c = ?"),
            "SELECT a FROM t WHERE b = $1 AND c = $2");
  EXPECT_EQ(ToPostgresParameters("UPDATE t SET a = ?1 WHERE b = ?2 OR c = ?1"),
            "UPDATE t SET a = $1 WHERE b = $2 OR c = $1");
  EXPECT_EQ(ToPostgresParameters("SELECT '?', \"a?\" FROM t WHERE x = ?"),
            "SELECT '?', \"a?\" FROM t WHERE x = $1");
}

// The GeoPackage reaches its schema by migrations, a PostGIS site is created from the
// description: the two must name the same columns in the same order.
TEST(SiteSchema, TheDescriptionIsWhatTheMigrationsBuild) {
  SqliteConnection connection(":memory:", SqliteDatabase::Mode::kCreate);
  MigrateSiteSchema(connection);
  SqliteDatabase& database = connection.database();
  std::size_t tables = 0;
  for (const TableSpec& table : SiteSchema()) {
    SqliteStatement columns =
        database.Prepare("SELECT name FROM pragma_table_info(?) ORDER BY cid");
    columns.Bind(1, std::string_view(table.name));
    std::vector<std::string> migrated, described;
    while (columns.Step()) migrated.push_back(columns.ColumnText(0));
    for (const ColumnSpec& column : table.columns) described.push_back(column.name);
    EXPECT_EQ(migrated, described) << table.name;
    ++tables;
  }
  SqliteStatement count = database.Prepare(
      "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name != 'sqlite_sequence'");
  ASSERT_TRUE(count.Step());
  EXPECT_EQ(static_cast<std::size_t>(count.ColumnInt64(0)), tables);
}

TEST(SiteSchema, PostgresTablesCarryTheSiteSridAndSpatialIndexes) {
  const std::string sql = PostgresSiteSchemaSql(32633);
  EXPECT_NE(sql.find("geom geometry(POINT, 32633) NOT NULL"), std::string::npos);
  EXPECT_NE(sql.find("geom geometry(LINESTRING, 32633) NOT NULL"), std::string::npos);
  EXPECT_NE(sql.find("CREATE INDEX litter_items_geom ON litter_items USING GIST (geom);"),
            std::string::npos);
  EXPECT_NE(sql.find("CREATE INDEX hotspots_geom ON hotspots USING GIST (geom);"),
            std::string::npos);
  EXPECT_NE(sql.find("UNIQUE (run_id, run_item_id)"), std::string::npos);
}

}  // namespace
}  // namespace littermap::db
