#include "heatmap/heatmap_files.hpp"

#include <cstdio>
#include <memory>
#include <optional>
#include <utility>

#include "core/output_folder.hpp"
#include "core/time.hpp"
#include "db/spatial_ref_sys.hpp"
#include "heatmap/density_preview.hpp"
#include "heatmap/exports.hpp"
#include "heatmap/geotiff_writer.hpp"
#include "heatmap/wgs84_transform.hpp"

namespace littermap::heatmap {
namespace {

void WriteRaster(const std::filesystem::path& file, const Raster& raster, const db::SiteInfo& site,
                 const std::string& citation, float nodata) {
  GeoTiffOptions options;
  options.epsg_code = site.frame.epsg_code;
  options.local_crs_name = db::LocalCrsName(site.name);
  options.citation = citation;
  options.nodata = nodata;
  WriteCloudOptimizedGeoTiff(file, raster, options);
}

}  // namespace

std::vector<std::string> HeatmapFileNames() {
  return {"density.tif", "effort.tif", "density.png", "hotspots.csv", "items.csv", "items.geojson"};
}

HeatmapFilesResult WriteHeatmapFiles(db::SiteDatabase& site, const std::filesystem::path& dir,
                                     HeatmapFilesOptions options) {
  PrepareOutputFolder(dir, {"-o", HeatmapFileNames(), options.force_output});
  options.hotspots.separation_m = options.map.density.kernel.bandwidth_m;
  const db::SiteFrame& frame = site.site().frame;
  const SiteHeatmap map = ComputeSiteHeatmap(site, options.map);

  const float nodata = options.map.density.nodata;
  WriteRaster(dir / "density.tif", map.density.density, site.site(),
              "littermap litter density, items per 100 m2 per survey", nodata);
  WriteRaster(dir / "effort.tif", map.effort, site.site(), "littermap survey effort, surveys",
              -1.0f);
  DensityPreviewOptions preview;
  preview.title =
      site.site().name + ": litter density (" + std::to_string(map.run_ids.size()) +
      (map.run_ids.size() == 1 ? " run" : " runs") +
      (options.map.class_name.empty() ? std::string() : ", class " + options.map.class_name) + ")";
  if (std::optional<db::SiteMapRecord> site_map = site.SiteMap()) {
    preview.occupancy_cell_size_m = site_map->image.resolution_m;
    preview.occupancy = [site_map = std::move(*site_map), frame](double x_m, double y_m) {
      return site_map.GreyAt(frame.FromCrs({x_m, y_m}));
    };
  }
  WriteDensityPreview(dir / "density.png", map.density.density, nodata, preview);

  std::vector<ClassifiedPoint> points;
  for (const auto& item : map.items) points.push_back({frame.ToCrs(item.site_xy), item.class_name});
  options.hotspots.min_effort_surveys = HotspotMinSurveys(map.run_ids.size());
  const auto hotspots =
      FindHotspots(map.density.density, nodata, points, options.hotspots, &map.effort);
  std::vector<db::HotspotRecord> records;
  for (const auto& h : hotspots) {
    records.push_back({h.rank, frame.FromCrs(h.crs), h.density_per_100m2, h.dominant_class});
  }
  const auto utc = [](const std::optional<double>& time_s) {
    return time_s ? FormatUtc(*time_s, "%Y-%m-%dT%H:%M:%SZ") : std::string();
  };
  char min_confidence[32] = "";
  if (options.map.min_confidence > 0.0) {
    std::snprintf(min_confidence, sizeof min_confidence, "%g", options.map.min_confidence);
  }
  const db::HotspotFilter filter{options.map.class_name, utc(options.map.from_time_s),
                                 utc(options.map.to_time_s), min_confidence};
  site.InTransaction([&] { site.ReplaceHotspots(filter, records); });

  HeatmapFilesResult result;
  std::unique_ptr<Wgs84Transform> wgs84;
  if (frame.georeferenced()) wgs84 = std::make_unique<Wgs84Transform>(frame.epsg_code);
  WriteHotspotsCsv(dir / "hotspots.csv", hotspots, frame, wgs84.get());
  const std::vector<LonLat> lonlat = ItemsLonLat(map.items, frame, wgs84.get());
  WriteItemsCsv(dir / "items.csv", map.items, frame, lonlat);
  if (wgs84) {
    WriteItemsGeoJson(dir / "items.geojson", map.items, lonlat);
  } else {
    result.warnings.push_back(site.name() +
                              ": the site is not georeferenced (no --crs at 'site init'), so "
                              "there is no items.geojson (GeoJSON is WGS 84 only)");
  }
  result.runs = map.run_ids.size();
  result.items = map.items.size();
  result.detections = map.detections;
  result.hotspots = hotspots.size();
  result.surveyed_area_m2 = map.density.surveyed_area_m2;
  result.max_density_per_100m2 = static_cast<double>(map.density.max_density);
  return result;
}

HeatmapFilesResult WriteHeatmapFiles(const db::SiteLocator& site_file,
                                     const std::filesystem::path& dir,
                                     HeatmapFilesOptions options) {
  db::SiteDatabase site = db::SiteDatabase::Open(site_file);
  return WriteHeatmapFiles(site, dir, std::move(options));
}

std::string HeatmapSummary(const HeatmapFilesResult& result, const std::filesystem::path& dir) {
  char figures[256];
  const auto s = [](std::size_t n) { return n == 1 ? "" : "s"; };
  std::snprintf(figures, sizeof figures,
                "%zu run%s, %zu item%s (%zu detection%s), %.0f m2 surveyed; peak density %.2f "
                "items per 100 m2 per survey; %zu hotspot%s; written to ",
                result.runs, s(result.runs), result.items, s(result.items), result.detections,
                s(result.detections), result.surveyed_area_m2, result.max_density_per_100m2,
                result.hotspots, s(result.hotspots));
  return figures + dir.string();
}

}  // namespace littermap::heatmap
