#pragma once
// The figures of a site report, computed from the site database over a period: what each run
// surveyed and found, how well it was reconstructed, where litter is densest and what it is.
// Everything a report shows (HTML or JSON) comes from here, so both always agree.
//
// Runs are ordered by start time. An item is "new" in the run that first saw it and "still
// there" in every later run that sees it again; it is "gone" from a run that looked at its place
// (the place is in the run's camera coverage) without finding it: picked up, or missed.

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "db/site_database.hpp"
#include "heatmap/hotspots.hpp"
#include "heatmap/site_heatmap.hpp"
#include "heatmap/wgs84_transform.hpp"

namespace littermap::reports {

struct SiteReportOptions {
  std::optional<double> from_time_s;  // runs starting at or after (Unix seconds)
  std::optional<double> to_time_s;    // runs starting before
  heatmap::SiteHeatmapOptions heatmap;
  int max_hotspots = 10;
  int hotspot_min_items = heatmap::HotspotOptions{}.min_items;  // distinct items a hotspot needs
  // A run covering less than this share of the ground the site's runs surveyed is flagged.
  double low_coverage_fraction = 0.5;
  double low_registration_quality = 0.6;  // runs matched onto the site map worse are flagged
};

using ClassCounts = std::map<std::string, int>;

// Reconstruction quality of a run, from reconstruct's quality.json (run/quality_file.hpp).
struct RunQuality {
  bool known = false;                   // the run came with a quality.json
  std::map<std::string, int> routines;  // scans per tracking routine
  int scans = 0;
  int key_frames = 0;
  int loop_closures_found = 0;
  int loop_closures_accepted = 0;

  // The share of the scans that only wheel odometry placed; 0 when unknown.
  double OdometryOnlyShare() const;
};

struct RunFigures {
  std::int64_t run_id = 0;
  std::string name;
  double start_time_s = 0.0;
  double end_time_s = 0.0;
  double length_m = 0.0;
  double observed_area_m2 = 0.0;
  double coverage_fraction = 0.0;  // of the ground any selected run observed
  std::size_t detections = 0;
  std::size_t items_found = 0;  // distinct items
  std::size_t new_items = 0;
  std::size_t items_still_there = 0;
  std::size_t items_gone = 0;
  double items_per_100m2 = 0.0;  // distinct items found per 100 m2 observed
  ClassCounts items_by_class;
  std::optional<double> registration_quality;
  RunQuality quality;
  std::vector<std::string> warnings;  // for people: what makes this run's figures less reliable
};

struct HotspotFigures {
  int rank = 0;
  db::PointXY site_xy;
  db::PointXY crs;
  std::optional<heatmap::LonLat> wgs84;  // georeferenced sites only
  double density_per_100m2 = 0.0;
  std::string dominant_class;
  ClassCounts items_by_class;        // distinct items within a kernel bandwidth of its peaks
  std::vector<db::PointXY> outline;  // CRS: the hull of its peaks' kernels (heatmap/hotspots)
  // The mean density each run found within a kernel bandwidth of here, in run order; none
  // where the run surveyed nothing of it.
  std::vector<std::optional<double>> density_by_run;
};

struct SiteReport {
  std::string site_name;
  db::SiteFrame frame;
  std::optional<double> from_time_s;
  std::optional<double> to_time_s;
  std::vector<RunFigures> runs;  // by start time
  std::size_t items = 0;         // distinct items the runs saw
  std::size_t detections = 0;
  ClassCounts items_by_class;
  double surveyed_area_m2 = 0.0;  // observed by at least one run
  double length_m = 0.0;
  double peak_density_per_100m2 = 0.0;
  double bandwidth_m = 0.0;
  double min_confidence = 0.0;  // detections less sure were left out
  int hotspot_min_items = 0;    // the support a hotspot needs (heatmap/hotspots.hpp)
  double hotspot_min_surveys = 0.0;
  float density_nodata = -9999.0f;  // density raster cells nobody surveyed
  std::vector<HotspotFigures> hotspots;
  std::vector<std::string> warnings;  // about the site as a whole
  heatmap::SiteHeatmap heatmap;       // what the maps are drawn from
  std::optional<db::SiteMapRecord> site_map;
};

// Throws BadInputError when no run of the site falls in the period.
SiteReport BuildSiteReport(db::SiteDatabase& site, const SiteReportOptions& options);

}  // namespace littermap::reports
