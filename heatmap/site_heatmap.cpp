#include "heatmap/site_heatmap.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.hpp"

namespace littermap::heatmap {
namespace {

GridGeometry UnionGrid(const std::vector<const db::CoverageRecord*>& coverages,
                       double cell_size_m) {
  double min_x = coverages[0]->min_x_m, max_y = coverages[0]->max_y_m;
  double max_x = min_x, min_y = max_y;
  for (const db::CoverageRecord* coverage : coverages) {
    const db::CoverageRecord& c = *coverage;
    min_x = std::min(min_x, c.min_x_m);
    max_y = std::max(max_y, c.max_y_m);
    max_x = std::max(max_x, c.min_x_m + c.width * c.cell_size_m);
    min_y = std::min(min_y, c.max_y_m - c.height * c.cell_size_m);
  }
  return GridGeometry::Covering(min_x, min_y, max_x, max_y, cell_size_m, 0.0);
}

// Adds one run's coverage: a site cell counts when the coverage cell under its centre does.
void AddRunEffort(Raster& effort, const db::CoverageRecord& coverage) {
  const GridGeometry& grid = effort.grid;
  for (int r = 0; r < grid.height; ++r) {
    const double y = grid.CellCenterY(r);
    const auto cr = static_cast<int>(std::floor((coverage.max_y_m - y) / coverage.cell_size_m));
    if (cr < 0 || cr >= coverage.height) continue;
    for (int c = 0; c < grid.width; ++c) {
      const double x = grid.CellCenterX(c);
      const auto cc = static_cast<int>(std::floor((x - coverage.min_x_m) / coverage.cell_size_m));
      if (cc < 0 || cc >= coverage.width) continue;
      effort.at(c, r) += coverage.observed[static_cast<std::size_t>(cr) * coverage.width + cc];
    }
  }
}

}  // namespace

SiteHeatmap ComputeSiteHeatmap(const SiteContents& site, const SiteHeatmapOptions& options) {
  if (!(options.cell_size_m > 0.0)) throw UsageError("heatmap: cell size must be > 0 m");
  if (!(options.min_confidence >= 0.0 && options.min_confidence <= 1.0)) {
    throw UsageError("heatmap: the minimum confidence must be in [0, 1]");
  }
  std::set<std::int64_t> selected;
  for (const db::RunRecord& run : site.runs) {
    if (options.from_time_s && run.start_time_s < *options.from_time_s) continue;
    if (options.to_time_s && run.start_time_s >= *options.to_time_s) continue;
    if (!options.run_ids.empty() && std::find(options.run_ids.begin(), options.run_ids.end(),
                                              run.run_id) == options.run_ids.end()) {
      continue;
    }
    selected.insert(run.run_id);
  }
  std::vector<const db::CoverageRecord*> coverages;
  for (const db::CoverageRecord& coverage : site.coverages) {
    if (selected.count(coverage.run_id)) coverages.push_back(&coverage);
  }
  if (coverages.empty()) {
    throw BadInputError(site.site_name +
                        ": no ingested run matches the selection (ingest runs first)");
  }
  SiteHeatmap heatmap;
  heatmap.run_ids.assign(selected.begin(), selected.end());
  heatmap.effort = Raster(UnionGrid(coverages, options.cell_size_m), 0.0f);
  for (const db::CoverageRecord* coverage : coverages) AddRunEffort(heatmap.effort, *coverage);

  const auto wanted = [&](const std::string& class_name) {
    return options.class_name.empty() || class_name == options.class_name;
  };
  // The detections of the selected runs, run by run, and the distinct items they are.
  std::vector<std::int64_t> fids;
  std::vector<db::PointXY> crs_points;
  for (const std::int64_t run_id : heatmap.run_ids) {
    const auto range = site.detections_of_run.find(run_id);
    if (range == site.detections_of_run.end()) continue;
    for (std::size_t i = range->second.first; i < range->second.second; ++i) {
      const db::DetectionRecord& detection = site.detections[i];
      if (detection.confidence < options.min_confidence) continue;
      if (detection.item_fid) fids.push_back(*detection.item_fid);
      if (wanted(detection.class_name)) crs_points.push_back(site.frame.ToCrs(detection.site_xy));
    }
  }
  std::sort(fids.begin(), fids.end());
  fids.erase(std::unique(fids.begin(), fids.end()), fids.end());
  for (const std::int64_t fid : fids) {
    const auto item = site.item_index.find(fid);
    if (item == site.item_index.end()) continue;
    if (wanted(site.items[item->second].class_name)) {
      heatmap.items.push_back(site.items[item->second]);
    }
  }
  heatmap.detections = crs_points.size();
  heatmap.density = EffortNormalisedDensity(heatmap.effort, crs_points, options.density);
  return heatmap;
}

SiteHeatmap ComputeSiteHeatmap(db::SiteDatabase& site, const SiteHeatmapOptions& options) {
  return ComputeSiteHeatmap(ReadSiteContents(site, options.min_confidence), options);
}

}  // namespace littermap::heatmap
