#pragma once
// `littermap heatmap` as a library call: a site's litter maps over a selection of its runs,
// written into one folder for GIS and people:
//   density.tif    litter density, items per 100 m2 per survey (Cloud Optimized GeoTIFF)
//   effort.tif     survey effort, surveys per cell
//   density.png    a preview of the density over the site map
//   hotspots.csv   the densest places, ranked, with their dominant class
//   items.csv      the distinct items the runs saw; items.geojson too when the site is
//                  georeferenced (GeoJSON is WGS 84 only)
// The hotspots are also stored in the site, for the report.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "db/site_database.hpp"
#include "heatmap/hotspots.hpp"
#include "heatmap/site_heatmap.hpp"

namespace littermap::heatmap {

struct HeatmapFilesOptions {
  SiteHeatmapOptions map;
  HotspotOptions hotspots;    // separation_m, min_effort_surveys: set from the density and runs
  bool force_output = false;  // write into a folder holding other files too
};

// The files WriteHeatmapFiles writes: density.tif, effort.tif, density.png, hotspots.csv,
// items.csv, items.geojson.
std::vector<std::string> HeatmapFileNames();

struct HeatmapFilesResult {
  std::size_t runs = 0;
  std::size_t items = 0;
  std::size_t detections = 0;
  std::size_t hotspots = 0;
  double surveyed_area_m2 = 0;
  double max_density_per_100m2 = 0;
  std::vector<std::string> warnings;
};

// Creates `dir` if needed. Throws BadInputError when no run matches the selection.
HeatmapFilesResult WriteHeatmapFiles(db::SiteDatabase& site, const std::filesystem::path& dir,
                                     HeatmapFilesOptions options);
// The same for the site `site_file` (a GeoPackage or a PostGIS site); throws BadInputError when it
// is not one.
HeatmapFilesResult WriteHeatmapFiles(const db::SiteLocator& site_file,
                                     const std::filesystem::path& dir, HeatmapFilesOptions options);

// What was written, in one line: runs, items, area, peak density, hotspots and `dir`.
std::string HeatmapSummary(const HeatmapFilesResult& result, const std::filesystem::path& dir);

}  // namespace littermap::heatmap
