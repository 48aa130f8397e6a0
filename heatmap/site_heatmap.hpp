#pragma once
// A site's survey effort and litter density over a selection of its runs, on a north-up grid
// in the site CRS that covers every selected run's camera coverage. The density counts
// detections, not distinct items: litter that stays is found again by every run that looks, so
// detections over effort is the litter a survey finds there on average, whatever the number
// of surveys (distinct items over effort would thin out litter the more often it is surveyed).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "db/site_database.hpp"
#include "heatmap/density_map.hpp"
#include "heatmap/raster.hpp"
#include "heatmap/site_contents.hpp"

namespace littermap::heatmap {

struct SiteHeatmapOptions {
  DensityMapOptions density;
  double cell_size_m = 0.5;
  std::string class_name;             // empty: every class
  std::optional<double> from_time_s;  // runs starting at or after (Unix seconds)
  std::optional<double> to_time_s;    // runs starting before
  std::vector<std::int64_t> run_ids;  // only these runs; empty: every run in the period
  // Detections less sure than this (their class's probability, items.csv "confidence") are left
  // out, as if never made: an item counts when a selected run saw it at least this surely.
  double min_confidence = 0.0;
};

struct SiteHeatmap {
  Raster effort;  // surveys per cell
  DensityMapResult density;
  std::vector<db::ItemRecord> items;  // the distinct items the selected runs saw (site frame)
  std::size_t detections = 0;         // what the density counts
  std::vector<std::int64_t> run_ids;
};

// Throws BadInputError when no run of the site matches the selection.
SiteHeatmap ComputeSiteHeatmap(const SiteContents& site, const SiteHeatmapOptions& options);
// The same, reading the site first.
SiteHeatmap ComputeSiteHeatmap(db::SiteDatabase& site, const SiteHeatmapOptions& options);

}  // namespace littermap::heatmap
