// The site commands on a PostGIS site: init, ingest, heatmap and report as on a GeoPackage; site
// export and import move a park between the engines without changing its report; GDAL (so QGIS)
// reads the PostGIS layers.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "support/run_command.hpp"
#include "support/site_engines.hpp"
#include "support/synthetic_run_dir.hpp"
#include "support/temp_dir.hpp"

namespace littermap {
namespace {

using test::Quote;
using test::RunCommand;
using test::RunLittermap;
using test::SiteEngine;
using test::TempDir;
using test::TestSite;
using test::WriteSyntheticRun;

std::string Slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void ExpectSameFiles(const std::filesystem::path& a, const std::filesystem::path& b,
                     const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    ASSERT_TRUE(std::filesystem::exists(a / name)) << a / name;
    EXPECT_EQ(Slurp(a / name), Slurp(b / name)) << name;
  }
}

TEST(SitePostgisCli, AParkMovesBetweenTheEnginesWithTheSameReport) {
  // Reports say when they were made: one time for all, or a minute's turn between two differs.
  setenv("SOURCE_DATE_EPOCH", "1793524800", 1);
  TempDir dir;
  TestSite postgis(SiteEngine::kPostgis, dir.path(), "park");
  const std::string site = Quote(postgis.argument());
  auto result = RunLittermap("site init " + site +
                             " --name 'North park' --crs EPSG:32633 --origin 500000 5000000");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  for (int week = 1; week <= 3; ++week) {
    const auto run = dir / ("week" + std::to_string(week));
    WriteSyntheticRun(run, 10.0 + 0.1 * week, 1.7e9 + 604800.0 * week, week == 2 ? "cup" : "can");
    result = RunLittermap("ingest " + site + " " + Quote(run) + " --name 'week " +
                          std::to_string(week) + "'");
    ASSERT_EQ(result.exit_code, 0) << result.output;
  }
  EXPECT_NE(result.output.find("9 seen again"), std::string::npos) << result.output;
  result = RunLittermap("-q ingest " + site + " " + Quote(dir / "week1") + " --name 'week 1'");
  EXPECT_NE(result.output.find("nothing changed"), std::string::npos) << result.output;
  ASSERT_EQ(RunLittermap("-q heatmap " + site + " -o " + Quote(dir / "maps")).exit_code, 0);
  ASSERT_EQ(RunLittermap("-q report " + site + " -o " + Quote(dir / "report")).exit_code, 0);
  EXPECT_NE(Slurp(dir / "report" / "report.json").find("\"generated_utc\": \"2026-11-01 09:20\""),
            std::string::npos);

  result = RunLittermap("-q site export " + site + " -o " + Quote(dir / "park.gpkg"));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find(": 3 runs, 9 items, 27 detections, 1 hotspots"), std::string::npos)
      << result.output;
  ASSERT_EQ(
      RunLittermap("-q report " + Quote(dir / "park.gpkg") + " -o " + Quote(dir / "report-gpkg"))
          .exit_code,
      0);
  ExpectSameFiles(dir / "report", dir / "report-gpkg", {"index.html", "report.json"});
  ASSERT_EQ(
      RunLittermap("-q heatmap " + Quote(dir / "park.gpkg") + " -o " + Quote(dir / "maps-gpkg"))
          .exit_code,
      0);
  ExpectSameFiles(dir / "maps", dir / "maps-gpkg",
                  {"items.csv", "hotspots.csv", "items.geojson", "density.tif", "effort.tif"});

  // And back: a second PostGIS site from the file, with the same report again.
  TestSite back(SiteEngine::kPostgis, dir.path(), "back");
  result = RunLittermap("-q site import " + Quote(dir / "park.gpkg") + " --site " +
                        Quote(back.argument()));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  ASSERT_EQ(
      RunLittermap("-q report " + Quote(back.argument()) + " -o " + Quote(dir / "report-back"))
          .exit_code,
      0);
  ExpectSameFiles(dir / "report", dir / "report-back", {"index.html", "report.json"});
  // A new run after the import takes new ids, not the copied ones.
  WriteSyntheticRun(dir / "week4", 10.5, 1.7e9 + 604800.0 * 4, "bottle");
  result = RunLittermap("ingest " + Quote(back.argument()) + " " + Quote(dir / "week4"));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("Ingested run 4 "), std::string::npos) << result.output;

  // The targets exist now: neither copy overwrites.
  EXPECT_EQ(RunLittermap("site export " + site + " -o " + Quote(dir / "park.gpkg")).exit_code, 1);
  EXPECT_EQ(
      RunLittermap("site import " + Quote(dir / "park.gpkg") + " --site " + Quote(back.argument()))
          .exit_code,
      1);
}

TEST(SitePostgisCli, GdalReadsThePostgisLayers) {
  TempDir dir;
  TestSite postgis(SiteEngine::kPostgis, dir.path(), "gdal");
  const std::string site = Quote(postgis.argument());
  ASSERT_EQ(RunLittermap("site init " + site + " --name p --crs EPSG:32633 --origin 500000 5000000")
                .exit_code,
            0);
  WriteSyntheticRun(dir / "run", 10.0, 1.7e9, "can");
  ASSERT_EQ(RunLittermap("-q ingest " + site + " " + Quote(dir / "run")).exit_code, 0);
  std::smatch match;
  const std::string url = test::PostgisTestUrl();
  ASSERT_TRUE(
      std::regex_match(url, match, std::regex(R"(postgresql://(\w+)@([\w.]+):(\d+)/(\w+))")))
      << url;
  const std::string connection = "PG:host=" + match[2].str() + " port=" + match[3].str() +
                                 " user=" + match[1].str() + " dbname=" + match[4].str() +
                                 " schemas=" + postgis.locator().schema;
  const auto info = RunCommand("ogrinfo -ro -so " + Quote(connection) + " litter_items");
  ASSERT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("Geometry: Point"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("Feature Count: 9"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("UTM zone 33N"), std::string::npos) << info.output;
  const auto tracks = RunCommand("ogrinfo -ro -so " + Quote(connection) + " run_tracks");
  EXPECT_NE(tracks.output.find("Geometry: Line String"), std::string::npos) << tracks.output;
}

TEST(SitePostgisCli, AUriWithoutASiteOrAServerIsAClearError) {
  auto result = RunLittermap("report postgresql:///city -o /tmp/never");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.output.find("names no site; add ?site=NAME"), std::string::npos)
      << result.output;
  result = RunLittermap("report 'postgresql://nobody@127.0.0.1:1/city?site=north' -o /tmp/never");
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.output.find("postgresql://nobody@127.0.0.1:1/city (site north): cannot connect"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(std::filesystem::exists("/tmp/never"));
}

}  // namespace
}  // namespace littermap
