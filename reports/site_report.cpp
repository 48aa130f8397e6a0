#include "reports/site_report.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "core/error.hpp"
#include "reports/html_text.hpp"
#include "run/quality_file.hpp"

namespace littermap::reports {
double RunQuality::OdometryOnlyShare() const {
  const auto odometry = routines.find("odometry-only");
  if (!known || scans == 0 || odometry == routines.end()) return 0.0;
  return static_cast<double>(odometry->second) / scans;
}

namespace {

std::vector<db::RunRecord> RunsByStartTime(const heatmap::SiteContents& site) {
  std::vector<db::RunRecord> runs = site.runs;
  std::stable_sort(runs.begin(), runs.end(),
                   [](const auto& a, const auto& b) { return a.start_time_s < b.start_time_s; });
  return runs;
}

// Reads reconstruct's quality.json as stored; its warnings go to `warnings`.
RunQuality ParseQuality(const db::RunRecord& run, std::vector<std::string>& warnings) {
  RunQuality quality;
  if (run.reconstruction_quality.empty()) return quality;
  const std::optional<run::ReconstructionQuality> record =
      run::QualityFromJson(run.reconstruction_quality);
  if (!record) {
    warnings.push_back("its reconstruction quality record is unreadable");
    return quality;
  }
  quality.known = true;
  quality.scans = static_cast<int>(record->scans);
  quality.key_frames = static_cast<int>(record->key_frames);
  quality.loop_closures_found = static_cast<int>(record->loop_closures_found);
  quality.loop_closures_accepted = static_cast<int>(record->loop_closures_accepted);
  for (const auto& [name, count] : record->routines) {
    quality.routines[name] = static_cast<int>(count);
  }
  for (const std::string& warning : record->warnings) {
    warnings.push_back("reconstruction: " + warning);
  }
  return quality;
}

void AddRunWarnings(const SiteReportOptions& options, RunFigures& run) {
  if (!run.quality.known) {
    run.warnings.push_back(
        "no reconstruction quality on record (ingested from a truth directory or by an older "
        "littermap)");
  } else if (const double share = run.quality.OdometryOnlyShare(); share > 0.1) {
    run.warnings.push_back(FormatPercent(share) +
                           " of the laser scans were placed by wheel odometry alone: items "
                           "may sit up to a metre off");
  }
  if (run.coverage_fraction < options.low_coverage_fraction) {
    run.warnings.push_back("covered " + FormatPercent(run.coverage_fraction) +
                           " of the surveyed ground: compare its counts per 100 m2, not in total");
  }
  if (run.registration_quality && *run.registration_quality < options.low_registration_quality) {
    run.warnings.push_back("matched onto the site map with a ratio of only " +
                           FormatPercent(*run.registration_quality) +
                           ": its items may be misplaced");
  }
}

// New, still there and gone per run, replaying every run of the site in start-time order (so
// the runs before the period set the state the period starts from).
void CountItemChanges(
    const heatmap::SiteContents& site, const std::vector<db::RunRecord>& all_runs,
    const std::unordered_map<std::int64_t, const db::CoverageRecord*>& coverage_by_run,
    std::vector<RunFigures>& figures) {
  std::unordered_map<std::int64_t, std::set<std::int64_t>> found_by_run;
  for (const db::DetectionRecord& d : site.detections) {
    if (d.item_fid) found_by_run[d.run_id].insert(*d.item_fid);
  }

  // Items present (seen, and not missed since) by 16 m square of the site CRS, so a run looks
  // only at those under its coverage: a site of years holds a million.
  constexpr double kSquareM = 16.0;
  const auto square = [](double x, double y) {
    return std::pair(static_cast<std::int64_t>(std::floor(x / kSquareM)),
                     static_cast<std::int64_t>(std::floor(y / kSquareM)));
  };
  const auto key = [](std::int64_t sx, std::int64_t sy) {
    return (sx * 73856093) ^ (sy * 19349663);
  };
  struct Present {
    std::int64_t fid;
    db::PointXY crs;
  };
  std::unordered_map<std::int64_t, std::vector<Present>> present_by_square;
  std::unordered_set<std::int64_t> present;
  std::unordered_set<std::int64_t> known;  // seen by some earlier run
  const db::SiteFrame& frame = site.frame;
  for (const db::RunRecord& run : all_runs) {
    const std::set<std::int64_t>& found = found_by_run[run.run_id];
    RunFigures* out = nullptr;
    for (RunFigures& f : figures) {
      if (f.run_id == run.run_id) out = &f;
    }
    const auto coverage = coverage_by_run.find(run.run_id);
    if (coverage != coverage_by_run.end()) {
      const db::CoverageRecord& c = *coverage->second;
      const auto [x0, y0] = square(c.min_x_m, c.max_y_m - c.height * c.cell_size_m);
      const auto [x1, y1] = square(c.min_x_m + c.width * c.cell_size_m, c.max_y_m);
      for (std::int64_t sx = x0; sx <= x1; ++sx) {
        for (std::int64_t sy = y0; sy <= y1; ++sy) {
          const auto cell = present_by_square.find(key(sx, sy));
          if (cell == present_by_square.end()) continue;
          std::vector<Present>& items = cell->second;
          for (std::size_t i = 0; i < items.size();) {
            if (square(items[i].crs.x, items[i].crs.y) == std::pair(sx, sy) &&
                c.Covers(items[i].crs) && !found.count(items[i].fid)) {
              if (out) ++out->items_gone;
              present.erase(items[i].fid);
              items[i] = items.back();
              items.pop_back();
            } else {
              ++i;
            }
          }
        }
      }
    }
    for (const std::int64_t fid : found) {
      const auto index = site.item_index.find(fid);
      const db::ItemRecord* item =
          index == site.item_index.end() ? nullptr : &site.items[index->second];
      if (out) {
        ++(known.count(fid) ? out->items_still_there : out->new_items);
        if (item) ++out->items_by_class[item->class_name];
      }
      known.insert(fid);
      if (item && present.insert(fid).second) {
        const db::PointXY crs = frame.ToCrs(item->site_xy);
        const auto [sx, sy] = square(crs.x, crs.y);
        present_by_square[key(sx, sy)].push_back({fid, crs});
      }
    }
    if (out) out->items_found = found.size();
  }
}

// The mean of a run's density over its surveyed cells within `radius_m` of a point: what the run
// found around a hotspot, even where the hotspot's own cell lies at the edge of its coverage.
std::optional<double> MeanWithin(const heatmap::Raster& density, const db::PointXY& crs,
                                 double radius_m, float nodata) {
  const heatmap::GridGeometry& grid = density.grid;
  double sum = 0;
  int cells = 0;
  for (int r = 0; r < grid.height; ++r) {
    const double dy = grid.CellCenterY(r) - crs.y;
    if (std::abs(dy) > radius_m) continue;
    for (int c = 0; c < grid.width; ++c) {
      const float value = density.at(c, r);
      if (value == nodata || std::hypot(grid.CellCenterX(c) - crs.x, dy) > radius_m) continue;
      sum += value;
      ++cells;
    }
  }
  return cells > 0 ? std::optional<double>(sum / cells) : std::nullopt;
}

}  // namespace

SiteReport BuildSiteReport(db::SiteDatabase& site, const SiteReportOptions& options) {
  SiteReport report;
  report.site_name = site.site().name;
  report.frame = site.site().frame;
  report.from_time_s = options.from_time_s;
  report.to_time_s = options.to_time_s;
  report.bandwidth_m = options.heatmap.density.kernel.bandwidth_m;
  report.density_nodata = options.heatmap.density.nodata;
  report.min_confidence = options.heatmap.min_confidence;

  heatmap::SiteHeatmapOptions heatmap_options = options.heatmap;
  heatmap_options.from_time_s = options.from_time_s;
  heatmap_options.to_time_s = options.to_time_s;
  heatmap_options.class_name.clear();
  heatmap_options.run_ids.clear();
  const heatmap::SiteContents contents =
      heatmap::ReadSiteContents(site, options.heatmap.min_confidence);
  report.heatmap = heatmap::ComputeSiteHeatmap(contents, heatmap_options);
  const heatmap::SiteHeatmap& map = report.heatmap;
  report.items = map.items.size();
  report.detections = map.detections;
  report.peak_density_per_100m2 = map.density.max_density;
  for (const db::ItemRecord& item : map.items) ++report.items_by_class[item.class_name];
  std::size_t surveyed_cells = 0;
  for (const float effort : map.effort.values) surveyed_cells += effort > 0.0f;
  report.surveyed_area_m2 = static_cast<double>(surveyed_cells) * map.effort.grid.cell_area_m2();
  report.site_map = site.SiteMap();

  // Every run of the site, read once: the runs before the period set the state it starts from.
  const std::vector<db::RunRecord> all_runs = RunsByStartTime(contents);
  std::unordered_map<std::int64_t, const db::CoverageRecord*> coverage_by_run;
  for (const db::CoverageRecord& c : contents.coverages) coverage_by_run[c.run_id] = &c;
  // The period's runs are those the heatmap selected.
  const std::set<std::int64_t> selected(map.run_ids.begin(), map.run_ids.end());
  for (const db::RunRecord& run : all_runs) {
    if (!selected.count(run.run_id)) continue;
    RunFigures& f = report.runs.emplace_back();
    f.run_id = run.run_id;
    f.name = run.name;
    f.start_time_s = run.start_time_s;
    f.end_time_s = run.end_time_s;
    f.length_m = run.length_m;
    const auto coverage = coverage_by_run.find(run.run_id);
    f.observed_area_m2 =
        coverage == coverage_by_run.end() ? 0.0 : coverage->second->observed_area_m2;
    f.coverage_fraction = report.surveyed_area_m2 > 0
                              ? std::min(1.0, f.observed_area_m2 / report.surveyed_area_m2)
                              : 0.0;
    const auto stored = contents.detections_of_run.find(run.run_id);
    f.detections = stored == contents.detections_of_run.end()
                       ? 0
                       : stored->second.second - stored->second.first;
    f.registration_quality = run.registration_quality;
    f.quality = ParseQuality(run, f.warnings);
    report.length_m += f.length_m;
  }
  CountItemChanges(contents, all_runs, coverage_by_run, report.runs);
  for (RunFigures& f : report.runs) {
    f.items_per_100m2 = f.observed_area_m2 > 0
                            ? 100.0 * static_cast<double>(f.items_found) / f.observed_area_m2
                            : 0.0;
    AddRunWarnings(options, f);
  }

  // Hotspots of the whole period, and how dense each run found them.
  std::vector<heatmap::ClassifiedPoint> points;
  for (const db::ItemRecord& item : map.items) {
    points.push_back({report.frame.ToCrs(item.site_xy), item.class_name});
  }
  heatmap::HotspotOptions hotspot_options;
  hotspot_options.min_effort_surveys = heatmap::HotspotMinSurveys(map.run_ids.size());
  hotspot_options.separation_m = report.bandwidth_m;
  hotspot_options.max_count = options.max_hotspots;
  hotspot_options.min_items = options.hotspot_min_items;
  report.hotspot_min_items = hotspot_options.min_items;
  report.hotspot_min_surveys = hotspot_options.min_effort_surveys;
  const float nodata = options.heatmap.density.nodata;
  // Each run's density, computed only for the runs whose coverage comes within reach of a
  // hotspot: of a site's thousand runs, most pass far from all twenty.
  std::vector<std::optional<heatmap::Raster>> run_density(report.runs.size());
  const auto run_density_near = [&](std::size_t i, const db::PointXY& crs) {
    const auto coverage = coverage_by_run.find(report.runs[i].run_id);
    if (coverage == coverage_by_run.end()) return false;
    const db::CoverageRecord* c = coverage->second;
    const double reach =
        report.bandwidth_m + 2.0 * std::max(c->cell_size_m, options.heatmap.cell_size_m);
    const bool near =
        crs.x >= c->min_x_m - reach && crs.x <= c->min_x_m + c->width * c->cell_size_m + reach &&
        crs.y <= c->max_y_m + reach && crs.y >= c->max_y_m - c->height * c->cell_size_m - reach;
    if (near && !run_density[i]) {
      heatmap::SiteHeatmapOptions one_run = heatmap_options;
      one_run.run_ids = {report.runs[i].run_id};
      run_density[i] = heatmap::ComputeSiteHeatmap(contents, one_run).density.density;
    }
    return near;
  };
  std::unique_ptr<heatmap::Wgs84Transform> wgs84;
  if (report.frame.georeferenced()) {
    wgs84 = std::make_unique<heatmap::Wgs84Transform>(report.frame.epsg_code);
  } else {
    report.warnings.push_back(
        "The site has a local frame (no --crs at 'site init'): positions are in metres from the "
        "dock, without GPS coordinates.");
  }
  for (const heatmap::Hotspot& h :
       heatmap::FindHotspots(map.density.density, nodata, points, hotspot_options, &map.effort)) {
    HotspotFigures& f = report.hotspots.emplace_back();
    f.rank = h.rank;
    f.crs = h.crs;
    f.site_xy = report.frame.FromCrs(h.crs);
    if (wgs84) f.wgs84 = (*wgs84)(h.crs);
    f.density_per_100m2 = h.density_per_100m2;
    f.dominant_class = h.dominant_class;
    f.items_by_class = h.items_by_class;
    f.outline = h.outline;
    for (std::size_t i = 0; i < report.runs.size(); ++i) {
      f.density_by_run.push_back(run_density_near(i, h.crs) ? MeanWithin(*run_density[i], h.crs,
                                                                         report.bandwidth_m, nodata)
                                                            : std::nullopt);
    }
  }
  return report;
}

}  // namespace littermap::reports
