// littermap ingest and heatmap on synthetic run directories: idempotent ingest, two ingests at
// once on one site, and the heatmap outputs.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/sqlite_database.hpp"
#include "support/run_command.hpp"
#include "support/synthetic_run_dir.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap {
namespace {

using test::RunLittermap;
using test::TempDir;
using test::WriteSyntheticRun;

std::int64_t Integer(const std::filesystem::path& file, const std::string& sql) {
  SqliteDatabase database(file, SqliteDatabase::Mode::kReadOnly);
  SqliteStatement query = database.Prepare(sql);
  return query.Step() ? query.ColumnInt64(0) : -1;
}

std::string Text(const std::filesystem::path& file, const std::string& sql) {
  SqliteDatabase database(file, SqliteDatabase::Mode::kReadOnly);
  SqliteStatement query = database.Prepare(sql);
  return query.Step() ? query.ColumnText(0) : "<no row>";
}

TEST(IngestHeatmapCli, IngestIsIdempotentAndHeatmapWritesEverything) {
  TempDir dir;
  const auto site = dir / "site.gpkg";
  WriteSyntheticRun(dir / "run1", 10.0, 1700000000.0, "can");
  ASSERT_EQ(RunLittermap("site init " + site.string() +
                         " --name p --crs EPSG:32633 --origin 500000 5000000")
                .exit_code,
            0);
  const auto first = RunLittermap("ingest " + site.string() + " " + (dir / "run1").string());
  ASSERT_EQ(first.exit_code, 0) << first.output;
  EXPECT_NE(first.output.find("9 new items"), std::string::npos) << first.output;
  const auto again = RunLittermap("ingest " + site.string() + " " + (dir / "run1").string());
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("nothing changed"), std::string::npos) << again.output;
  EXPECT_EQ(Integer(site, "SELECT count(*) FROM litter_items"), 9);
  EXPECT_EQ(Integer(site, "SELECT count(*) FROM detections"), 9);

  const auto out = dir / "out";
  const auto heatmap = RunLittermap("heatmap " + site.string() + " -o " + out.string());
  ASSERT_EQ(heatmap.exit_code, 0) << heatmap.output;
  for (const char* name :
       {"density.tif", "effort.tif", "hotspots.csv", "items.csv", "items.geojson", "density.png"}) {
    EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
  }
  std::ifstream geojson(out / "items.geojson");
  const auto json = nlohmann::json::parse(geojson);
  EXPECT_EQ(json["features"].size(), 9u);
  const double lon = json["features"][0]["geometry"]["coordinates"][0];
  EXPECT_NEAR(lon, 15.0, 0.01);  // 500 km easting in UTM 33N is 15 deg E
  EXPECT_GT(Integer(site, "SELECT count(*) FROM hotspots"), 0);
  EXPECT_EQ(Text(site, "PRAGMA integrity_check"), "ok");
  EXPECT_EQ(Text(site, "PRAGMA foreign_key_check"), "<no row>");
}

// A site one may only read (mode 0444 in a folder of mode 0555, as on a share): `report` reads
// it and leaves it as it was. File modes do not stop root, so as root the command runs as the
// user nobody.
TEST(IngestHeatmapCli, ReportReadsASiteItMayNotWrite) {
  TempDir dir;
  namespace fs = std::filesystem;
  fs::create_directories(dir / "share");
  const fs::path site = dir / "share" / "site.gpkg";
  ASSERT_EQ(RunLittermap("-q site init " + test::Quote(site) + " --name p").exit_code, 0);
  WriteSyntheticRun(dir / "run1", 10.0, 1700000000.0, "can");
  ASSERT_EQ(
      RunLittermap("-q ingest " + test::Quote(site) + " " + test::Quote(dir / "run1")).exit_code,
      0);
  const std::string before = test::Slurp(site);
  fs::permissions(site, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  fs::permissions(dir / "share", fs::perms::owner_read | fs::perms::owner_exec |
                                     fs::perms::group_read | fs::perms::group_exec |
                                     fs::perms::others_read | fs::perms::others_exec);
  fs::create_directories(dir / "out");
  fs::permissions(dir / "out", fs::perms::all);
  fs::permissions(dir.path(), fs::perms::all);
  const std::string as_reader =
      geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  const test::CommandResult result =
      test::RunCommand(as_reader + LITTERMAP_EXECUTABLE + " -q report " + test::Quote(site) +
                       " -o " + test::Quote(dir / "out" / "report"));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "report" / "index.html"));
  EXPECT_EQ(test::Slurp(site), before);
  EXPECT_FALSE(fs::exists(site.string() + "-wal"));
  // A command that writes the site says that it cannot, as an environment fault.
  if (!as_reader.empty()) {
    const test::CommandResult heatmap =
        test::RunCommand(as_reader + LITTERMAP_EXECUTABLE + " -q heatmap " + test::Quote(site) +
                         " -o " + test::Quote(dir / "out" / "maps"));
    EXPECT_EQ(heatmap.exit_code, 4) << heatmap.output;
    EXPECT_NE(heatmap.output.substr(0, heatmap.output.find('\n')).find(site.string()),
              std::string::npos)
        << heatmap.output;
  }
  fs::permissions(dir / "share", fs::perms::owner_all);
}

TEST(IngestHeatmapCli, TwoIngestsAtOnceBothLand) {
  TempDir dir;
  const auto site = dir / "site.gpkg";
  ASSERT_EQ(RunLittermap("site init " + site.string() + " --name p").exit_code, 0);
  for (int i = 0; i < 4; ++i) {
    WriteSyntheticRun(dir / ("run" + std::to_string(i)), 5.0 * i, 1700000000.0 + 1000 * i,
                      i % 2 ? "cup" : "can");
  }
  // Four processes started together; SQLite's busy timeout serialises their transactions.
  std::string command;
  for (int i = 0; i < 4; ++i) {
    command += std::string(LITTERMAP_EXECUTABLE) + " -q ingest " + site.string() + " " +
               (dir / ("run" + std::to_string(i))).string() + " > " +
               (dir / ("log" + std::to_string(i))).string() + " 2>&1 & ";
  }
  command += "wait";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_EQ(Integer(site, "SELECT count(*) FROM runs"), 4);
  EXPECT_EQ(Integer(site, "SELECT count(*) FROM coverage"), 4);
  EXPECT_EQ(Integer(site, "SELECT count(*) FROM run_tracks"), 4);
  EXPECT_EQ(Integer(site, "SELECT count(*) FROM detections"), 36);
  EXPECT_EQ(Text(site, "PRAGMA integrity_check"), "ok");
  EXPECT_EQ(Text(site, "PRAGMA foreign_key_check"), "<no row>");
}

TEST(IngestHeatmapCli, RefusesWhatIsNotASite) {
  TempDir dir;
  WriteSyntheticRun(dir / "run", 0.0, 0.0, "can");
  std::ofstream(dir / "notes.gpkg") << "plain text, not SQLite at all, long enough to be a header "
                                       "of one hundred bytes if SQLite tried to read it as one";
  const auto text =
      RunLittermap("ingest " + (dir / "notes.gpkg").string() + " " + (dir / "run").string());
  EXPECT_EQ(text.exit_code, 2) << text.output;
  EXPECT_NE(text.output.find("notes.gpkg: not a GeoPackage"), std::string::npos) << text.output;
  const auto missing =
      RunLittermap("heatmap " + (dir / "none.gpkg").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
}

TEST(IngestHeatmapCli, RunNamesAreNeverEmptyNorSilentlyTwiceAndOutputsNeverAFile) {
  TempDir dir;
  const auto site = dir / "site.gpkg";
  ASSERT_EQ(RunLittermap("site init " + site.string() + " --name p").exit_code, 0);
  WriteSyntheticRun(dir / "week1", 10.0, 1700000000.0, "can");
  WriteSyntheticRun(dir / "other" / "week1", 20.0, 1700005000.0, "cup");
  const auto slash = RunLittermap("ingest " + site.string() + " " + (dir / "week1").string() + "/");
  ASSERT_EQ(slash.exit_code, 0) << slash.output;
  EXPECT_EQ(Text(site, "SELECT name FROM runs"), "week1");
  // Other results under the same folder name are refused, not stored as a second "week1".
  const auto twice =
      RunLittermap("ingest " + site.string() + " " + (dir / "other" / "week1").string());
  EXPECT_EQ(twice.exit_code, 2) << twice.output;
  EXPECT_NE(twice.output.find("already holds a run named 'week1' with other results"),
            std::string::npos)
      << twice.output;
  EXPECT_EQ(Integer(site, "SELECT COUNT(*) FROM runs"), 1);
  const auto renamed = RunLittermap("ingest " + site.string() + " " +
                                    (dir / "other" / "week1").string() + " --name 'week 1, east'");
  EXPECT_EQ(renamed.exit_code, 0) << renamed.output;

  std::ofstream(dir / "taken") << "a file, not a folder";
  const auto file = RunLittermap("heatmap " + site.string() + " -o " + (dir / "taken").string());
  EXPECT_EQ(file.exit_code, 1) << file.output;
  EXPECT_NE(file.output.find("-o " + (dir / "taken").string() + ": is a file, not a folder"),
            std::string::npos)
      << file.output;
  const auto root = RunLittermap("report " + site.string() + " -o /");
  EXPECT_EQ(root.exit_code, 1) << root.output;
  EXPECT_NE(root.output.find("-o /: holds"), std::string::npos) << root.output;
}

// The GIS layers say what they show and GDAL 3.6 (Debian 12's, under its QGIS) reads them
// without a warning: run tracks carry their run's name and start, a heatmap of one class keeps
// the hotspots of all litter, and a local site's CRS has one name in the GeoPackage and the
// rasters.
TEST(IngestHeatmapCli, GisLayersSayWhatTheyShowAndGdalReadsThemQuietly) {
  ASSERT_EQ(test::RunCommand("command -v ogrinfo gdalinfo").exit_code, 0)
      << "gdal-bin is a test dependency (scripts/install-deps.sh)";
  TempDir dir;
  for (const bool georeferenced : {true, false}) {
    const auto site = dir / (georeferenced ? "utm.gpkg" : "local.gpkg");
    ASSERT_EQ(RunLittermap("-q site init " + test::Quote(site) + " --name 'North Park'" +
                           (georeferenced ? " --crs EPSG:32633 --origin 500000 5000000" : ""))
                  .exit_code,
              0);
    // Four runs along one path: every 4 m three cans and a bottle lie within a metre or two.
    WriteSyntheticRun(dir / "week1", 10.0, 1795000000.0, "can");
    WriteSyntheticRun(dir / "week2", 11.0, 1795600000.0, "bottle");
    WriteSyntheticRun(dir / "week3", 12.0, 1796200000.0, "can");
    WriteSyntheticRun(dir / "week4", 9.0, 1796800000.0, "can");
    for (const char* run : {"week1", "week2", "week3", "week4"}) {
      ASSERT_EQ(
          RunLittermap("-q ingest " + test::Quote(site) + " " + test::Quote(dir / run)).exit_code,
          0);
    }
    const std::string maps = test::Quote(dir / "maps");
    ASSERT_EQ(
        RunLittermap("-q heatmap " + test::Quote(site) + " -o " + maps + " --force").exit_code, 0);
    ASSERT_EQ(
        RunLittermap("-q heatmap " + test::Quote(site) + " -o " + maps + " --force --class can")
            .exit_code,
        0);
    EXPECT_GT(Integer(site, "SELECT count(*) FROM hotspots WHERE filter_class = ''"), 0);
    EXPECT_GT(Integer(site, "SELECT count(*) FROM hotspots WHERE filter_class = 'can'"), 0);
    EXPECT_EQ(Integer(site, "SELECT count(*) FROM hotspots WHERE dominant_class = ''"), 0);
    EXPECT_EQ(Text(site, "SELECT run_name || ' ' || start_utc FROM run_tracks ORDER BY run_id"),
              "week1 2026-11-18T11:06:40Z");
    EXPECT_EQ(Integer(site, "PRAGMA user_version"), 10300);

    const test::CommandResult layers = test::RunCommand("ogrinfo -ro -al -so " + test::Quote(site));
    EXPECT_EQ(layers.exit_code, 0) << layers.output;
    EXPECT_EQ(layers.output.find("Warning"), std::string::npos) << layers.output;
    EXPECT_NE(layers.output.find("run_name: String"), std::string::npos) << layers.output;
    EXPECT_NE(layers.output.find("filter_class: String"), std::string::npos) << layers.output;
    const test::CommandResult raster =
        test::RunCommand("gdalinfo " + test::Quote(dir / "maps" / "density.tif"));
    EXPECT_EQ(raster.exit_code, 0) << raster.output;
    EXPECT_EQ(raster.output.find("Warning"), std::string::npos) << raster.output;
    const test::CommandResult effort =
        test::RunCommand("gdalinfo " + test::Quote(dir / "maps" / "effort.tif"));
    EXPECT_EQ(effort.exit_code, 0) << effort.output;
    EXPECT_EQ(effort.output.find("Warning"), std::string::npos) << effort.output;
    if (georeferenced) {
      const test::CommandResult geojson =
          test::RunCommand("ogrinfo -ro -al -so " + test::Quote(dir / "maps" / "items.geojson"));
      EXPECT_EQ(geojson.exit_code, 0) << geojson.output;
      EXPECT_EQ(geojson.output.find("Warning"), std::string::npos) << geojson.output;
      // the last heatmap was of cans: three runs of nine
      EXPECT_NE(geojson.output.find("Feature Count: 27"), std::string::npos) << geojson.output;
    }
    if (!georeferenced) {
      const std::string name = "littermap site frame: North Park";
      EXPECT_NE(layers.output.find("ENGCRS[\"" + name), std::string::npos) << layers.output;
      EXPECT_NE(raster.output.find(name), std::string::npos) << raster.output;
    }
    std::filesystem::remove_all(dir / "maps");
  }
}

}  // namespace
}  // namespace littermap
