// Run item files, hotspots, the WGS 84 transform and the CSV/GeoJSON exports.

#include <gtest/gtest.h>

#include <algorithm>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.hpp"
#include "heatmap/exports.hpp"
#include "heatmap/hotspots.hpp"
#include "heatmap/wgs84_transform.hpp"
#include "support/temp_dir.hpp"
#include "support/test_files.hpp"

namespace littermap::heatmap {
namespace {

using littermap::test::TempDir;

using test::Slurp;

TEST(Wgs84Transform, UtmCentralMeridianOnTheEquator) {
  // UTM zone 33N: false easting 500 km on the central meridian 15 deg E.
  const Wgs84Transform wgs84(32633);
  const LonLat ll = wgs84({500000.0, 0.0});
  EXPECT_NEAR(ll.lon_deg, 15.0, 1e-9);
  EXPECT_NEAR(ll.lat_deg, 0.0, 1e-9);
  const LonLat north = wgs84({500000.0, 1000.0});  // 1 km north: about 0.00904 deg
  EXPECT_NEAR(north.lat_deg, 1000.0 / 110574.0, 1e-5);
  // Many points at once give what one at a time gives.
  const std::vector<db::PointXY> points = {{500000.0, 0.0}, {500000.0, 1000.0}, {612345.6, 5e6}};
  const std::vector<LonLat> many = wgs84(points);
  ASSERT_EQ(many.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(many[i].lon_deg, wgs84(points[i]).lon_deg) << i;
    EXPECT_EQ(many[i].lat_deg, wgs84(points[i]).lat_deg) << i;
  }
  EXPECT_TRUE(wgs84(std::vector<db::PointXY>()).empty());
}

// 20 x 20 cells of 1 m, (0, 0) to (20, 20).
GridGeometry MetreGrid20() {
  GridGeometry grid;
  grid.max_y_m = 20.0;
  grid.cell_size_m = 1.0;
  grid.width = grid.height = 20;
  return grid;
}

TEST(Hotspots, RanksPeaksAndNamesTheirClass) {
  const GridGeometry grid = MetreGrid20();
  Raster density(grid, 0.0f);
  density.at(5, 5) = 3.0f;
  density.at(6, 5) = 2.0f;  // shoulder of the first peak, not a peak itself
  density.at(15, 15) = 5.0f;
  density.at(0, 19) = -9999.0f;
  const std::vector<ClassifiedPoint> items = {
      {{5.5, 14.5}, "can"}, {{15.5, 4.5}, "cup"}, {{15.0, 4.0}, "cup"}, {{15.6, 4.6}, "can"}};
  HotspotOptions options;
  options.min_items = 1;
  const auto hotspots = FindHotspots(density, -9999.0f, items, options);
  ASSERT_EQ(hotspots.size(), 2u);
  EXPECT_EQ(hotspots[0].rank, 1);
  EXPECT_EQ(hotspots[0].density_per_100m2, 5.0);
  EXPECT_DOUBLE_EQ(hotspots[0].crs.x, 15.5);
  EXPECT_DOUBLE_EQ(hotspots[0].crs.y, 4.5);
  EXPECT_EQ(hotspots[0].dominant_class, "cup");
  EXPECT_EQ(hotspots[0].items_nearby(), 3);
  EXPECT_EQ(hotspots[1].dominant_class, "can");
}

// Peaks whose kernels overlap are one place to clean, outlined around both; a place with too
// few items, or on ground surveyed too rarely, is not called a hotspot.
TEST(Hotspots, OverlappingPeaksAreOneAreaWithSupport) {
  const GridGeometry grid = MetreGrid20();
  Raster density(grid, 0.0f);
  Raster effort(grid, 3.0f);
  density.at(4, 10) = 4.0f;   // (4.5, 9.5)
  density.at(9, 10) = 3.0f;   // (9.5, 9.5): 5 m on, kernels of 3 m overlap
  density.at(16, 2) = 6.0f;   // (16.5, 17.5): one item only
  density.at(16, 17) = 7.0f;  // (16.5, 2.5): three items, surveyed once
  effort.at(16, 17) = 1.0f;
  const std::vector<ClassifiedPoint> items = {
      {{4.0, 9.0}, "can"},  {{5.0, 10.0}, "can"}, {{10.0, 9.5}, "bottle"}, {{16.5, 17.5}, "cup"},
      {{16.0, 2.0}, "cup"}, {{17.0, 2.0}, "cup"}, {{16.5, 3.0}, "cup"}};
  HotspotOptions options;
  options.min_items = 3;
  options.min_effort_surveys = 2;
  const auto hotspots = FindHotspots(density, -9999.0f, items, options, &effort);
  ASSERT_EQ(hotspots.size(), 1u);
  const Hotspot& area = hotspots[0];
  EXPECT_EQ(area.rank, 1);
  EXPECT_DOUBLE_EQ(area.crs.x, 4.5);  // the densest point of the area
  EXPECT_EQ(area.peaks.size(), 2u);
  EXPECT_EQ(area.items_nearby(), 3);
  EXPECT_EQ(area.items_by_class.at("can"), 2);
  EXPECT_EQ(area.dominant_class, "can");
  double min_x = 1e9, max_x = -1e9;
  for (const db::PointXY& p : area.outline) {
    min_x = std::min(min_x, p.x);
    max_x = std::max(max_x, p.x);
  }
  EXPECT_NEAR(min_x, 4.5 - 3.0, 0.01);  // around both kernels
  EXPECT_NEAR(max_x, 9.5 + 3.0, 0.01);
  // Without the effort gate the densest place (three items, surveyed once) is first.
  const auto ungated = FindHotspots(density, -9999.0f, items, options);
  ASSERT_EQ(ungated.size(), 2u);
  EXPECT_DOUBLE_EQ(ungated[0].crs.y, 2.5);
  options.max_count = 0;
  EXPECT_TRUE(FindHotspots(density, -9999.0f, items, options).empty());
}

TEST(Exports, GeoJsonIsRfc7946LonLat) {
  TempDir dir;
  db::SiteFrame frame;
  frame.srs_id = frame.epsg_code = 32633;
  frame.origin_easting_m = 500000.0;
  std::vector<db::ItemRecord> items = {{7, "plastic \"bag\"", {0.0, 0.0}, 0, 0.3, 0.9, 1, 2, 2}};
  const Wgs84Transform wgs84(32633);
  WriteItemsGeoJson(dir / "items.geojson", items, ItemsLonLat(items, frame, &wgs84));
  const auto json = nlohmann::json::parse(Slurp(dir / "items.geojson"));
  EXPECT_EQ(json["type"], "FeatureCollection");
  EXPECT_FALSE(json.contains("crs"));  // RFC 7946 removed it: WGS 84 only
  ASSERT_EQ(json["features"].size(), 1u);
  const auto& feature = json["features"][0];
  EXPECT_EQ(feature["geometry"]["type"], "Point");
  EXPECT_NEAR(feature["geometry"]["coordinates"][0].get<double>(), 15.0, 1e-7);  // lon first
  EXPECT_NEAR(feature["geometry"]["coordinates"][1].get<double>(), 0.0, 1e-7);
  EXPECT_EQ(feature["properties"]["class"], "plastic \"bag\"");
  EXPECT_EQ(feature["properties"]["times_seen"], 2);

  WriteItemsCsv(dir / "items.csv", items, frame, {});
  const std::string csv = Slurp(dir / "items.csv");
  EXPECT_NE(
      csv.find("\n7,\"plastic \"\"bag\"\"\",0.000,0.000,500000.000,0.000,,,0.300,0.900,1,2,2\n"),
      std::string::npos)
      << csv;

  // A class name a spreadsheet would run as a formula is exported as text.
  items[0].class_name = "=cmd|' /C calc'!A0";
  items[0].fid = 8;
  WriteItemsCsv(dir / "formula.csv", items, frame, {});
  const std::string formula = Slurp(dir / "formula.csv");
  EXPECT_NE(formula.find("\n8,\"'=cmd|' /C calc'!A0\",0.000"), std::string::npos) << formula;
  for (const char* start : {"+1", "-1", "@SUM(A1)"}) {
    items[0].class_name = start;
    WriteItemsCsv(dir / "formula.csv", items, frame, {});
    EXPECT_NE(Slurp(dir / "formula.csv").find(std::string("\n8,\"'") + start + "\","),
              std::string::npos)
        << start;
  }
}

}  // namespace
}  // namespace littermap::heatmap
