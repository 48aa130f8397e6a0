#include "db/site_database.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <fstream>

#include "core/error.hpp"
#include "db/geopackage_schema.hpp"
#include "db/site_migrations.hpp"
#include "support/site_options.hpp"
#include "support/temp_dir.hpp"

namespace littermap::db {
namespace {

using littermap::test::SiteOptionsOf;
using littermap::test::TempDir;

std::string Text(SqliteDatabase& database, const std::string& sql) {
  SqliteStatement query = database.Prepare(sql);
  return query.Step() ? query.ColumnText(0) : "<no row>";
}

std::int64_t Integer(SqliteDatabase& database, const std::string& sql) {
  SqliteStatement query = database.Prepare(sql);
  return query.Step() ? query.ColumnInt64(0) : -999;
}

TEST(SiteDatabase, LocalSiteIsAValidGeoPackage) {
  TempDir dir;
  SiteDatabase site = SiteDatabase::Create(dir / "park.gpkg", SiteOptionsOf("North park"));
  SqliteDatabase& sql = site.sqlite();
  EXPECT_EQ(Integer(sql, "PRAGMA application_id"), 0x47504B47);
  EXPECT_EQ(Integer(sql, "PRAGMA user_version"), 10300);  // GeoPackage 1.3
  EXPECT_EQ(Text(sql, "PRAGMA integrity_check"), "ok");
  EXPECT_EQ(Text(sql, "PRAGMA foreign_key_check"), "<no row>");
  EXPECT_EQ(Integer(sql, "PRAGMA foreign_keys"), 1);
  EXPECT_EQ(Text(sql, "PRAGMA journal_mode"), "wal");
  // The three rows every GeoPackage must hold, plus the site frame.
  EXPECT_EQ(Text(sql, "SELECT organization FROM gpkg_spatial_ref_sys WHERE srs_id = 4326"), "EPSG");
  EXPECT_EQ(Text(sql, "SELECT definition FROM gpkg_spatial_ref_sys WHERE srs_id = -1"),
            "undefined");
  EXPECT_EQ(Text(sql, "SELECT definition FROM gpkg_spatial_ref_sys WHERE srs_id = 0"), "undefined");
  EXPECT_EQ(Integer(sql, "SELECT count(*) FROM gpkg_spatial_ref_sys WHERE srs_id = 100000"), 1);
  EXPECT_EQ(Integer(sql,
                    "SELECT count(*) FROM gpkg_contents WHERE data_type = 'features' AND "
                    "srs_id = 100000"),
            3);
  EXPECT_EQ(Text(sql,
                 "SELECT geometry_type_name FROM gpkg_geometry_columns "
                 "WHERE table_name = 'run_tracks'"),
            "LINESTRING");
  EXPECT_EQ(Text(sql,
                 "SELECT geometry_type_name FROM gpkg_geometry_columns "
                 "WHERE table_name = 'litter_items' AND column_name = 'geom'"),
            "POINT");
  EXPECT_EQ(site.site().name, "North park");
  EXPECT_FALSE(site.site().frame.georeferenced());
  EXPECT_EQ(site.site().schema_version, LatestSiteSchemaVersion());
}

TEST(SiteDatabase, EpsgSiteCarriesProjDefinition) {
  TempDir dir;
  SiteDatabase site =
      SiteDatabase::Create(dir / "park.gpkg", SiteOptionsOf("Madison", 32616, 305000, 4770000, 90));
  const std::string definition =
      Text(site.sqlite(), "SELECT definition FROM gpkg_spatial_ref_sys WHERE srs_id = 32616");
  EXPECT_EQ(definition.rfind("PROJCS[\"WGS 84 / UTM zone 16N\"", 0), 0u) << definition;
  EXPECT_EQ(site.site().frame.srs_id, 32616);
  // Rotation 90 deg: the site x axis points north.
  const PointXY crs = site.site().frame.ToCrs({10, 0});
  EXPECT_NEAR(crs.x, 305000, 1e-9);
  EXPECT_NEAR(crs.y, 4770010, 1e-9);
}

TEST(SiteDatabase, RefusesUnusableCrsAndLeavesNoFile) {
  TempDir dir;
  EXPECT_THROW(SiteDatabase::Create(dir / "a.gpkg", SiteOptionsOf("a", 4326)), UsageError);
  EXPECT_THROW(SiteDatabase::Create(dir / "a.gpkg", SiteOptionsOf("a", 999999)), UsageError);
  EXPECT_THROW(SiteDatabase::Create(dir / "a.gpkg", SiteOptionsOf("a", std::nullopt, 0, 0, 5)),
               UsageError);
  EXPECT_FALSE(std::filesystem::exists(dir / "a.gpkg"));
}

TEST(SiteDatabase, ReopensWithRecordsAndGeometryInTheSiteCrs) {
  TempDir dir;
  const auto file = dir / "park.gpkg";
  {
    SiteDatabase site = SiteDatabase::Create(file, SiteOptionsOf("p", 32633, 500000, 5000000, 30));
    site.InTransaction([&] {
      const std::int64_t run =
          site.AddRun({0, "run1", "digest-1", 0, 900, 120, {}, std::nullopt, {}});
      const std::vector<PointXY> track = {{0, 0}, {3, 4}, {3, 10}};
      site.AddRunTrack(run, track);
      site.AddItem({0, "bottle", {3, 4}, 0.05, 0.2, 0.9, run, run, 1});
    });
    EXPECT_THROW(site.AddRun({0, "again", "digest-1", 0, 1, 1, {}, std::nullopt, {}}),
                 SqliteError);  // unique digest
  }
  SiteDatabase site = SiteDatabase::Open(file);
  EXPECT_EQ(site.site().frame.epsg_code, 32633);
  EXPECT_DOUBLE_EQ(site.site().frame.rotation_deg, 30);
  ASSERT_TRUE(site.FindRun("digest-1").has_value());
  EXPECT_FALSE(site.FindRun("digest-2").has_value());
  const auto tracks = site.RunTracks();
  ASSERT_EQ(tracks.size(), 1u);
  ASSERT_EQ(tracks[0].site_points.size(), 3u);
  EXPECT_NEAR(tracks[0].site_points[2].y, 10, 1e-9);
  const auto items = site.Items();
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0].class_name, "bottle");
  // The stored geometry is in EPSG:32633, not the site frame.
  SqliteStatement geom = site.sqlite().Prepare("SELECT geom FROM litter_items");
  ASSERT_TRUE(geom.Step());
  const GeometryBlob blob = DecodeGeometry(geom.ColumnBlob(0), "test");
  const PointXY expected = site.site().frame.ToCrs({3, 4});
  EXPECT_EQ(blob.srs_id, 32633);
  EXPECT_NEAR(blob.points[0].x, expected.x, 1e-9);
  EXPECT_NEAR(blob.points[0].y, expected.y, 1e-9);
  EXPECT_NEAR(expected.x, 500000 + 3 * std::cos(M_PI / 6) - 4 * std::sin(M_PI / 6), 1e-9);
  EXPECT_EQ(Integer(site.sqlite(),
                    "SELECT count(*) FROM gpkg_contents WHERE "
                    "table_name = 'litter_items' AND min_x IS NOT NULL"),
            1);
  EXPECT_EQ(Text(site.sqlite(), "PRAGMA integrity_check"), "ok");
  EXPECT_EQ(Text(site.sqlite(), "PRAGMA foreign_key_check"), "<no row>");
}

TEST(SiteDatabase, ASiteMissingATableOrColumnIsRefusedWhenOpened) {
  TempDir dir;
  { SiteDatabase::Create(dir / "park.gpkg", SiteOptionsOf("North park")); }
  {
    SqliteDatabase raw(dir / "park.gpkg", SqliteDatabase::Mode::kReadWrite);
    raw.Execute("ALTER TABLE runs DROP COLUMN reconstruction_quality");
  }
  try {
    SiteDatabase::Open(dir / "park.gpkg");
    ADD_FAILURE() << "a site without runs.reconstruction_quality opened";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("no column runs.reconstruction_quality"),
              std::string::npos)
        << e.what();
  }
}

TEST(SiteDatabase, OutOfRangeOriginsAndNamesThatAreNotUtf8AreRefused) {
  TempDir dir;
  EXPECT_THROW(SiteDatabase::Create(dir / "a.gpkg", SiteOptionsOf("a", 32632, 9e8, 9e8, 0)),
               UsageError);
  EXPECT_THROW(SiteDatabase::Create(dir / "b.gpkg", SiteOptionsOf("b", 32632, NAN, 5334000, 0)),
               UsageError);
  EXPECT_THROW(
      SiteDatabase::Create(dir / "c.gpkg", SiteOptionsOf("Park \xC3", 32632, 691000, 5334000, 0)),
      BadInputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "a.gpkg"));
  EXPECT_NO_THROW(
      SiteDatabase::Create(dir / "d.gpkg", SiteOptionsOf("d", 32632, 691000, 5334000, 0)));
}

TEST(SiteDatabase, ForeignKeysAreEnforced) {
  TempDir dir;
  SiteDatabase site = SiteDatabase::Create(dir / "park.gpkg", SiteOptionsOf("p"));
  EXPECT_THROW(site.AddItem({0, "can", {1, 1}, 0, 0.1, 1, 42, 42, 1}), SqliteError);
}

TEST(SiteDatabase, RefusesFilesThatAreNotSiteGeoPackages) {
  TempDir dir;
  const auto text = dir / "notes.gpkg";
  std::ofstream(text) << "this is not an SQLite database, just some text that is long enough "
                         "to fill the SQLite header of one hundred bytes................";
  try {
    SiteDatabase::Open(text);
    FAIL() << "opened a text file";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("notes.gpkg: not a GeoPackage"), std::string::npos)
        << e.what();
  }
  const auto plain = dir / "plain.db";
  { SqliteDatabase(plain, SqliteDatabase::Mode::kCreate).Execute("CREATE TABLE t (x)"); }
  try {
    SiteDatabase::Open(plain);
    FAIL() << "opened a plain SQLite database";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("application_id is 0x00000000"), std::string::npos)
        << e.what();
  }
  const auto bare = dir / "bare.gpkg";
  {
    SqliteDatabase database(bare, SqliteDatabase::Mode::kCreate);
    CreateGeoPackageCore(database);
  }
  try {
    SiteDatabase::Open(bare);
    FAIL() << "opened a GeoPackage that is not a site";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a littermap site database"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(SiteDatabase::Open(dir / "missing.gpkg"), BadInputError);
  EXPECT_THROW(SiteDatabase::Create(bare, SiteOptionsOf("x")), UsageError);  // exists
}

TEST(SiteDatabase, RefusesASchemaFromTheFuture) {
  TempDir dir;
  const auto file = dir / "park.gpkg";
  {
    SiteDatabase site = SiteDatabase::Create(file, SiteOptionsOf("p"));
    site.sqlite().Execute(
        "INSERT INTO littermap_schema_version (version, description) "
        "VALUES (999, 'future')");
  }
  try {
    SiteDatabase::Open(file);
    FAIL() << "opened a newer schema";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find("schema version 999"), std::string::npos) << e.what();
  }
}

TEST(SiteDatabase, KeepsTheSiteMapAndWhereEachRunWasPlaced) {
  TempDir dir;
  const auto file = dir / "park.gpkg";
  {
    SiteDatabase site = SiteDatabase::Create(file, SiteOptionsOf("p"));
    RunRecord first{0, "first", "digest-1", 0, 10, 5, {}, std::nullopt, {}};
    RunRecord second{0, "second", "digest-2", 20, 30, 5, {1.5, -2.0, 0.25}, 0.87, {}};
    const std::int64_t first_id = site.AddRun(first);
    site.AddRun(second);
    EXPECT_FALSE(site.SiteMap());
    SiteMapRecord map;
    map.run_id = first_id;
    map.image.resolution_m = 0.05;
    map.image.origin_x_m = -3;
    map.image.origin_y_m = -4;
    map.image.width = 3;
    map.image.height = 2;
    map.T_site_map = {0.5, 0.25, 0.1};
    map.image.pixels = {0, 254, 205, 205, 0, 254};
    site.SetSiteMap(map);
    EXPECT_THROW(site.SetSiteMap(map), InternalError);  // one map per site
  }
  SiteDatabase site = SiteDatabase::Open(file);
  const std::vector<RunRecord> runs = site.Runs();
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_FALSE(runs[0].registration_quality);
  EXPECT_DOUBLE_EQ(runs[1].T_site_run.x_m, 1.5);
  EXPECT_DOUBLE_EQ(runs[1].T_site_run.y_m, -2.0);
  EXPECT_DOUBLE_EQ(runs[1].T_site_run.theta_rad, 0.25);
  EXPECT_DOUBLE_EQ(*runs[1].registration_quality, 0.87);
  const std::optional<SiteMapRecord> map = site.SiteMap();
  ASSERT_TRUE(map);
  EXPECT_EQ(map->run_id, runs[0].run_id);
  EXPECT_EQ(map->image.width, 3);
  EXPECT_EQ(map->image.height, 2);
  EXPECT_DOUBLE_EQ(map->image.origin_y_m, -4);
  EXPECT_DOUBLE_EQ(map->T_site_map.theta_rad, 0.1);
  EXPECT_EQ(map->image.pixels, (std::vector<std::uint8_t>{0, 254, 205, 205, 0, 254}));
}

TEST(SiteDatabase, AVersionOneSiteIsMigratedOnOpen) {
  TempDir dir;
  const auto file = dir / "park.gpkg";
  {
    SiteDatabase site = SiteDatabase::Create(file, SiteOptionsOf("p"));
    const std::int64_t run_id =
        site.AddRun({0, "week 1", "d1", 1795000000.0, 1795000600.0, 3, {}, std::nullopt, ""});
    const PointXY track[] = {{0, 0}, {3, 0}};
    site.AddRunTrack(run_id, track);
    // Back to version 1, as littermap wrote it then (declaring GeoPackage 1.4).
    site.sqlite().Execute("DROP TABLE site_map");
    site.sqlite().Execute("ALTER TABLE runs DROP COLUMN reconstruction_quality");
    for (const char* column : {"run_name", "start_utc"}) {
      site.sqlite().Execute(std::string("ALTER TABLE run_tracks DROP COLUMN ") + column);
    }
    for (const char* column :
         {"filter_class", "filter_from_utc", "filter_to_utc", "filter_min_confidence"}) {
      site.sqlite().Execute(std::string("ALTER TABLE hotspots DROP COLUMN ") + column);
    }
    site.sqlite().Execute("DROP INDEX litter_items_site_x_m_site_y_m");
    site.sqlite().Execute("PRAGMA user_version = 10400");
    site.sqlite().Execute("DELETE FROM littermap_schema_version WHERE version > 1");
  }
  SiteDatabase site = SiteDatabase::Open(file);
  EXPECT_EQ(site.site().schema_version, 6);
  EXPECT_TRUE(site.sqlite().HasColumn("hotspots", "filter_min_confidence"));
  EXPECT_EQ(Integer(site.sqlite(), "PRAGMA user_version"), 10300);
  EXPECT_EQ(Integer(site.sqlite(),
                    "SELECT count(*) FROM sqlite_master WHERE name = "
                    "'litter_items_site_x_m_site_y_m'"),
            1);
  EXPECT_EQ(Text(site.sqlite(), "SELECT run_name || ' ' || start_utc FROM run_tracks"),
            "week 1 2026-11-18T11:06:40Z");
  EXPECT_TRUE(site.sqlite().HasTable("site_map"));
  EXPECT_FALSE(site.SiteMap());
  RunRecord run{0, "r", "digest", 1, 2, 3, {}, std::nullopt, R"({"key_frames": 5})"};
  site.AddRun(run);
  EXPECT_EQ(site.Runs().back().reconstruction_quality, run.reconstruction_quality);
}

}  // namespace
}  // namespace littermap::db
