// littermap heatmap SITE.gpkg -o DIR [--from DATE --to DATE --class C]: survey effort and
// effort-normalised litter density of a site as Cloud-Optimized GeoTIFFs and a PNG preview,
// hotspots, and the items as CSV and GeoJSON.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/date_argument.hpp"
#include "core/error.hpp"
#include "db/site_database.hpp"
#include "heatmap/density_preview.hpp"
#include "heatmap/exports.hpp"
#include "heatmap/geotiff_writer.hpp"
#include "heatmap/hotspots.hpp"
#include "heatmap/site_heatmap.hpp"
#include "heatmap/wgs84_transform.hpp"

namespace littermap::cli {
namespace {

struct HeatmapArguments {
  std::string site;
  std::string output;
  std::string from;
  std::string to;
  heatmap::SiteHeatmapOptions options;
  heatmap::HotspotOptions hotspots;
};

void WriteRaster(const std::filesystem::path& file, const heatmap::Raster& raster,
                 const db::SiteFrame& frame, const std::string& citation, float nodata) {
  heatmap::GeoTiffOptions options;
  options.epsg_code = frame.epsg_code;
  options.citation = citation;
  options.nodata = nodata;
  heatmap::WriteCloudOptimizedGeoTiff(file, raster, options);
}

void RunHeatmap(HeatmapArguments arguments, CliContext& context) {
  arguments.options.from_time_s = ParseDateArgument(arguments.from, "--from");
  arguments.options.to_time_s = ParseDateArgument(arguments.to, "--to");
  arguments.hotspots.separation_m = arguments.options.density.kernel.bandwidth_m;
  db::SiteDatabase site = db::SiteDatabase::Open(arguments.site);
  const db::SiteFrame& frame = site.site().frame;
  const heatmap::SiteHeatmap map = heatmap::ComputeSiteHeatmap(site, arguments.options);

  const std::filesystem::path dir = arguments.output;
  std::filesystem::create_directories(dir);
  const float nodata = arguments.options.density.nodata;
  WriteRaster(dir / "density.tif", map.density.density, frame,
              "littermap litter density, items per 100 m2 per survey", nodata);
  WriteRaster(dir / "effort.tif", map.effort, frame, "littermap survey effort, surveys", -1.0f);
  heatmap::DensityPreviewOptions preview;
  preview.title =
      site.site().name + ": litter density (" + std::to_string(map.run_ids.size()) +
      (map.run_ids.size() == 1 ? " run" : " runs") +
      (arguments.options.class_name.empty() ? std::string()
                                            : ", class " + arguments.options.class_name) +
      ")";
  if (std::optional<db::SiteMapRecord> site_map = site.SiteMap()) {
    preview.occupancy_cell_size_m = site_map->image.resolution_m;
    preview.occupancy = [site_map = std::move(*site_map), frame](double x_m, double y_m) {
      return site_map.GreyAt(frame.FromCrs({x_m, y_m}));
    };
  }
  heatmap::WriteDensityPreview(dir / "density.png", map.density.density, nodata, preview);

  std::vector<heatmap::ClassifiedPoint> points;
  for (const auto& item : map.items) points.push_back({frame.ToCrs(item.site_xy), item.class_name});
  const auto hotspots =
      heatmap::FindHotspots(map.density.density, nodata, points, arguments.hotspots);
  std::vector<db::HotspotRecord> records;
  for (const auto& h : hotspots) {
    records.push_back({h.rank, frame.FromCrs(h.crs), h.density_per_100m2, h.dominant_class});
  }
  site.InTransaction([&] { site.ReplaceHotspots(records); });

  std::unique_ptr<heatmap::Wgs84Transform> wgs84;
  if (frame.georeferenced()) wgs84 = std::make_unique<heatmap::Wgs84Transform>(frame.epsg_code);
  heatmap::WriteHotspotsCsv(dir / "hotspots.csv", hotspots, frame, wgs84.get());
  heatmap::WriteItemsCsv(dir / "items.csv", map.items, frame, wgs84.get());
  if (wgs84) {
    heatmap::WriteItemsGeoJson(dir / "items.geojson", map.items, frame, *wgs84);
  } else {
    context.Warn(arguments.site +
                 ": the site is not georeferenced (no --crs at 'site init'), so there is no "
                 "items.geojson (GeoJSON is WGS 84 only)");
  }
  std::printf(
      "%zu runs, %zu items (%zu detections), %.0f m2 surveyed; peak density %.2f items per "
      "100 m2 per survey; %zu hotspots; written to %s\n",
      map.run_ids.size(), map.items.size(), map.detections, map.density.surveyed_area_m2,
      static_cast<double>(map.density.max_density), hotspots.size(), dir.c_str());
}

}  // namespace

void RegisterHeatmapCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<HeatmapArguments>();
  CLI::App* command = context.AddCommand(app, "heatmap", "Litter density maps of a site");
  command->add_option("SITE", arguments->site, "Site database (SITE.gpkg)")->required();
  command->add_option("-o,--output", arguments->output, "Output directory")->required();
  command->add_option("--from", arguments->from, "Only runs starting on or after (YYYY-MM-DD)");
  command->add_option("--to", arguments->to, "Only runs starting before (YYYY-MM-DD)");
  auto& options = arguments->options;
  command->add_option("--class", options.class_name, "Only items of this class");
  command->add_option("--cell-size", options.cell_size_m, "Raster cell size (m)")
      ->capture_default_str();
  command
      ->add_option("--bandwidth", options.density.kernel.bandwidth_m, "Quartic kernel radius (m)")
      ->capture_default_str();
  command
      ->add_option("--min-effort", options.density.min_effort_surveys,
                   "Cells surveyed fewer times are nodata")
      ->capture_default_str();
  command->add_option("--hotspots", arguments->hotspots.max_count, "Number of hotspots listed")
      ->capture_default_str();
  command->callback([arguments, &context] {
    context.run = [arguments, &context] { RunHeatmap(*arguments, context); };
  });
}

}  // namespace littermap::cli
