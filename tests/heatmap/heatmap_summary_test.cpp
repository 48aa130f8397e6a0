// What `littermap heatmap` tells the user about the files it wrote.

#include <gtest/gtest.h>

#include "heatmap/heatmap_files.hpp"

namespace littermap::heatmap {
namespace {

TEST(HeatmapSummary, CountsRunsItemsAndHotspotsAndNamesTheFolder) {
  HeatmapFilesResult result;
  result.runs = 3;
  result.items = 21;
  result.detections = 36;
  result.surveyed_area_m2 = 484.6;
  result.max_density_per_100m2 = 23.834;
  result.hotspots = 10;
  EXPECT_EQ(HeatmapSummary(result, "week1/maps"),
            "3 runs, 21 items (36 detections), 485 m2 surveyed; peak density 23.83 items per "
            "100 m2 per survey; 10 hotspots; written to week1/maps");
  result.runs = result.items = result.detections = result.hotspots = 1;
  EXPECT_EQ(HeatmapSummary(result, "maps").substr(0, 30), "1 run, 1 item (1 detection), 4");
  EXPECT_NE(HeatmapSummary(result, "maps").find("; 1 hotspot; "), std::string::npos);
}

}  // namespace
}  // namespace littermap::heatmap
