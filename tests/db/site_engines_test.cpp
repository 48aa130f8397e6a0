// One site, both engines: what is written reads back the same from a GeoPackage and from
// PostGIS, geometry lands in the site CRS on each, and each refuses what it must.

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "db/postgres_connection.hpp"
#include "db/site_database.hpp"
#include "support/site_engines.hpp"
#include "support/site_options.hpp"
#include "support/temp_dir.hpp"

namespace littermap::db {
namespace {

using littermap::test::SiteEngine;
using littermap::test::SiteOptionsOf;
using littermap::test::TempDir;
using littermap::test::TestSite;

std::string Text(SqlConnection& connection, const std::string& sql) {
  const auto query = connection.Prepare(sql);
  return query->Step() ? query->ColumnText(0) : "<no row>";
}

class SiteEnginesTest : public ::testing::TestWithParam<SiteEngine> {
 protected:
  TempDir dir_;
  TestSite where_{GetParam(), dir_.path(), "park"};
};

INSTANTIATE_TEST_SUITE_P(Engines, SiteEnginesTest,
                         ::testing::Values(SiteEngine::kGeoPackage, SiteEngine::kPostgis),
                         littermap::test::SiteEngineName);

TEST_P(SiteEnginesTest, EveryRecordReadsBackAsWritten) {
  std::int64_t run_id = 0, fid = 0;
  {
    SiteDatabase site = SiteDatabase::Create(
        where_.locator(), SiteOptionsOf("Park \xC3\xA9", 32633, 500000, 5e6, 30));
    site.InTransaction([&] {
      run_id = site.AddRun({0,
                            "week 1",
                            "digest-1",
                            1.7e9 + 0.25,
                            1.7e9 + 900,
                            120.5,
                            {1.5, -2.0, 0.25},
                            0.87,
                            R"({"routine":"laser"})"});
      site.AddRunTrack(run_id, std::vector<PointXY>{{0, 0}, {3, 4}, {3, 10}});
      fid = site.AddItem({0, "bottle", {3, 4}, 0.05, 0.2, 0.9, run_id, run_id, 1});
      site.AddDetection({run_id, fid, "7", "can", {3.1, 4.1}, 0.04, 0.19, 0.8});
      site.AddDetection({run_id, std::nullopt, "8", "cup", {5, 5}, 0.0, 0.1, 1.0 / 3.0});
      CoverageRecord coverage;
      coverage.run_id = run_id;
      coverage.cell_size_m = 0.5;
      coverage.min_x_m = 499990;
      coverage.max_y_m = 5000020;
      coverage.width = 3;
      coverage.height = 2;
      coverage.observed_area_m2 = 1.0;
      coverage.observed = {0, 1, 1, 0, 0, 1};
      site.AddCoverage(coverage);
      SiteMapRecord map;
      map.run_id = run_id;
      map.image.resolution_m = 0.05;
      map.image.width = 2;
      map.image.height = 2;
      map.image.pixels = {0, 254, 205, 0};
      map.T_site_map = {0.5, 0.25, 0.1};
      site.SetSiteMap(map);
    });
    site.ReplaceHotspots({"bottle", "", "", ""}, {{1, {3, 4}, 12.5, "bottle"}});
    site.MarkItemSeen(fid, run_id);
  }
  SiteDatabase site = SiteDatabase::OpenReadOnly(where_.locator());
  EXPECT_EQ(site.site().name, "Park \xC3\xA9");
  EXPECT_EQ(site.site().frame.epsg_code, 32633);
  EXPECT_DOUBLE_EQ(site.site().frame.rotation_deg, 30);
  EXPECT_EQ(site.site().created_utc.size(), 24u);  // 2026-12-05T04:21:12.123Z
  const std::vector<RunRecord> runs = site.Runs();
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].name, "week 1");
  EXPECT_EQ(runs[0].start_time_s, 1.7e9 + 0.25);  // doubles exactly, through text too
  EXPECT_EQ(runs[0].length_m, 120.5);
  EXPECT_EQ(runs[0].T_site_run.theta_rad, 0.25);
  EXPECT_EQ(*runs[0].registration_quality, 0.87);
  EXPECT_EQ(runs[0].reconstruction_quality, R"({"routine":"laser"})");
  const auto tracks = site.RunTracks();
  ASSERT_EQ(tracks.size(), 1u);
  ASSERT_EQ(tracks[0].site_points.size(), 3u);
  EXPECT_NEAR(tracks[0].site_points[2].x, 3, 1e-9);
  EXPECT_NEAR(tracks[0].site_points[2].y, 10, 1e-9);
  const auto items = site.Items();
  ASSERT_EQ(items.size(), 1u);
  EXPECT_EQ(items[0].fid, fid);
  EXPECT_EQ(items[0].times_seen, 2);
  EXPECT_EQ(items[0].confidence, 0.9);
  const auto detections = site.Detections({run_id});
  ASSERT_EQ(detections.size(), 2u);
  EXPECT_EQ(detections[0].item_fid, fid);
  EXPECT_FALSE(detections[1].item_fid);
  EXPECT_EQ(detections[1].confidence, 1.0 / 3.0);
  const auto coverages = site.Coverages();
  ASSERT_EQ(coverages.size(), 1u);
  EXPECT_EQ(coverages[0].observed, (std::vector<std::uint8_t>{0, 1, 1, 0, 0, 1}));
  const auto map = site.SiteMap();
  ASSERT_TRUE(map);
  EXPECT_EQ(map->image.pixels, (std::vector<std::uint8_t>{0, 254, 205, 0}));
  EXPECT_EQ(map->T_site_map.theta_rad, 0.1);
  // The geometry is in the site CRS, EPSG:32633, not the site frame.
  const PointXY crs = site.site().frame.ToCrs({3, 4});
  if (GetParam() == SiteEngine::kPostgis) {
    EXPECT_EQ(Text(site.sql(), "SELECT ST_SRID(geom) FROM litter_items"), "32633");
    EXPECT_NEAR(std::stod(Text(site.sql(), "SELECT ST_X(geom) FROM litter_items")), crs.x, 1e-9);
    EXPECT_NEAR(std::stod(Text(site.sql(), "SELECT ST_Y(geom) FROM hotspots")), crs.y, 1e-9);
    EXPECT_EQ(Text(site.sql(), "SELECT ST_NPoints(geom) FROM run_tracks"), "3");
    EXPECT_EQ(Text(site.sql(), "SELECT start_utc FROM run_tracks"), "2023-11-14T22:13:20Z");
    EXPECT_EQ(Text(site.sql(),
                   "SELECT count(*) FROM pg_indexes WHERE schemaname = current_schema() AND "
                   "indexdef LIKE '%USING gist (geom)%'"),
              "3");
  } else {
    EXPECT_EQ(Text(site.sql(), "SELECT start_utc FROM run_tracks"), "2023-11-14T22:13:20Z");
    EXPECT_EQ(Text(site.sql(), "PRAGMA integrity_check"), "ok");
  }
}

TEST_P(SiteEnginesTest, ALocalSiteHasNoCrs) {
  SiteDatabase::Create(where_.locator(), SiteOptionsOf("Local"));
  SiteDatabase site = SiteDatabase::Open(where_.locator());
  EXPECT_FALSE(site.site().frame.georeferenced());
  const std::int64_t run = site.AddRun({0, "r", "d", 0, 1, 1, {}, std::nullopt, {}});
  site.AddItem({0, "can", {-2.5, 7}, 0, 0.1, 1, run, run, 1});
  EXPECT_EQ(site.Items()[0].site_xy.x, -2.5);
  if (GetParam() == SiteEngine::kPostgis) {
    EXPECT_EQ(Text(site.sql(), "SELECT ST_AsText(geom) || ' ' || ST_SRID(geom) FROM litter_items"),
              "POINT(-2.5 7) 0");
  }
}

TEST_P(SiteEnginesTest, ASiteIsCreatedOnceAndOpenedOnlyWhenThere) {
  EXPECT_FALSE(SiteDatabase::Exists(where_.locator()));
  try {
    SiteDatabase::Open(where_.locator());
    FAIL() << "opened a site that is not there";
  } catch (const BadInputError& e) {
    EXPECT_NE(std::string(e.what()).find(where_.locator().display), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("site init"), std::string::npos) << e.what();
  }
  SiteDatabase::Create(where_.locator(), SiteOptionsOf("p"));
  EXPECT_TRUE(SiteDatabase::Exists(where_.locator()));
  try {
    SiteDatabase::Create(where_.locator(), SiteOptionsOf("p"));
    FAIL() << "created twice";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()),
              where_.locator().display + ": already exists; a site database is created only once");
  }
  // A refused CRS leaves nothing behind.
  TestSite other(GetParam(), dir_.path(), "other");
  EXPECT_THROW(SiteDatabase::Create(other.locator(), SiteOptionsOf("o", 4326)), UsageError);
  EXPECT_FALSE(SiteDatabase::Exists(other.locator()));
}

TEST_P(SiteEnginesTest, AColumnMissingIsNamedWhenOpened) {
  {
    SiteDatabase site = SiteDatabase::Create(where_.locator(), SiteOptionsOf("p"));
    site.sql().Execute("ALTER TABLE detections DROP COLUMN confidence");
  }
  try {
    SiteDatabase::Open(where_.locator());
    FAIL() << "opened a damaged site";
  } catch (const BadInputError& e) {
    EXPECT_EQ(std::string(e.what()),
              where_.locator().display +
                  ": not a complete littermap site database (damaged, or written by another "
                  "program): no column detections.confidence");
  }
}

TEST_P(SiteEnginesTest, AFailedTransactionLeavesNothing) {
  SiteDatabase site = SiteDatabase::Create(where_.locator(), SiteOptionsOf("p"));
  EXPECT_THROW(site.InTransaction([&] {
    site.AddRun({0, "r", "d", 0, 1, 1, {}, std::nullopt, {}});
    throw BadInputError("stop");
  }),
               BadInputError);
  EXPECT_TRUE(site.Runs().empty());
  site.AddRun({0, "r", "d", 0, 1, 1, {}, std::nullopt, {}});
  try {  // the digest is unique
    site.AddRun({0, "again", "d", 0, 1, 1, {}, std::nullopt, {}});
    FAIL() << "a digest twice";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(where_.locator().display), std::string::npos) << e.what();
  }
}

// A PostGIS site made at version 4 (before the items' coordinate index and the hotspots'
// confidence filter) gets them when a writing command opens it; a reading one says that it
// needs that.
TEST(PostgisSite, AnOlderSiteIsMigratedOnOpen) {
  TempDir dir;
  TestSite where(SiteEngine::kPostgis, dir.path(), "v4");
  {
    SiteDatabase site = SiteDatabase::Create(where.locator(), SiteOptionsOf("p"));
    site.sql().Execute("DROP INDEX litter_items_site_x_m_site_y_m");
    site.sql().Execute("ALTER TABLE hotspots DROP COLUMN filter_min_confidence");
    site.sql().Execute("UPDATE littermap_schema_version SET version = 4");
  }
  EXPECT_THROW(SiteDatabase::OpenReadOnly(where.locator()), BadInputError);
  SiteDatabase site = SiteDatabase::Open(where.locator());
  EXPECT_EQ(site.site().schema_version, 6);
  EXPECT_TRUE(site.sql().HasColumn("hotspots", "filter_min_confidence"));
  EXPECT_EQ(Text(site.sql(),
                 "SELECT count(*) FROM pg_indexes WHERE schemaname = current_schema() AND "
                 "indexname = 'litter_items_site_x_m_site_y_m'"),
            "1");
}

// Two SERIALIZABLE writers that each read the items of one place and add one there: PostgreSQL
// lets the first commit and aborts the second (40001), which runs again from the start and then
// sees the first's item. Neither write is lost; a failure that is not a conflict is not retried.
TEST(PostgisSite, ATransactionAbortedForAConflictRunsAgain) {
  TempDir dir;
  TestSite where(SiteEngine::kPostgis, dir.path(), "conflict");
  SiteDatabase first = SiteDatabase::Create(where.locator(), SiteOptionsOf("p"));
  SiteDatabase second = SiteDatabase::Open(where.locator());
  std::int64_t run_id = 0;
  first.InTransaction([&] { run_id = first.AddRun({0, "r", "d", 0, 1, 1, {}, std::nullopt, {}}); });
  for (SiteDatabase* site : {&first, &second}) {
    dynamic_cast<PostgresConnection&>(site->sql())
        .set_write_serialisation(PostgresWriteSerialisation::kSerializableTransactions);
  }
  const Envelope place{0, 10, 0, 10};
  int attempts = 0;
  std::vector<std::size_t> seen;  // items the second writer saw, on each attempt
  second.InTransaction([&] {
    ++attempts;
    seen.push_back(second.ItemsWithin(place).size());
    if (attempts == 1) {
      first.InTransaction([&] {
        first.ItemsWithin(place);
        first.AddItem({0, "can", {2, 2}, 0, 0.1, 0.9, run_id, run_id, 1});
      });
    }
    second.AddItem({0, "cup", {5, 5}, 0, 0.1, 0.9, run_id, run_id, 1});
  });
  EXPECT_EQ(attempts, 2);
  EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(second.conflicts_retried(), 1u);
  EXPECT_EQ(first.conflicts_retried(), 0u);
  EXPECT_EQ(first.Items().size(), 2u);

  attempts = 0;
  EXPECT_THROW(second.InTransaction([&] {
    ++attempts;
    throw BadInputError("not a conflict");
  }),
               BadInputError);
  EXPECT_EQ(attempts, 1);
}

TEST(PostgisSite, AServerThatIsNotThereIsTheEnvironment) {
  const SiteLocator where = ParseSiteLocator("postgresql://nobody@127.0.0.1:1/none?site=park");
  try {
    SiteDatabase::Open(where);
    FAIL() << "connected to nothing";
  } catch (const EnvironmentError&) {
    FAIL() << "a PostgresError is expected";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kEnvironment);
    EXPECT_EQ(
        std::string(e.what()).rfind("postgresql://nobody@127.0.0.1:1/none (site park): cannot "
                                    "connect: ",
                                    0),
        0u)
        << e.what();
  }
}

}  // namespace
}  // namespace littermap::db
