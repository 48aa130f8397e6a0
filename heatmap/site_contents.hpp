#pragma once
// What the heatmap and the report read of a site, read once: a report computes a heatmap of the
// period and one per run, and a site of a city park holds 1,000 runs and 1,000,000 items, so
// reading the tables again for each would be the report's whole time.

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "db/site_database.hpp"

namespace littermap::heatmap {

struct SiteContents {
  std::string site_name;  // for messages: the file, or the database and site
  db::SiteFrame frame;
  std::vector<db::RunRecord> runs;              // by run id
  std::vector<db::CoverageRecord> coverages;    // by run id
  std::vector<db::ItemRecord> items;            // by fid
  std::vector<db::DetectionRecord> detections;  // by run id, each run's in the order stored

  // The items by fid, and each run's detections: [first, last) of `detections`.
  std::unordered_map<std::int64_t, std::size_t> item_index;
  std::unordered_map<std::int64_t, std::pair<std::size_t, std::size_t>> detections_of_run;
};

// Detections with a confidence below `min_confidence` are left out, as if never made, so every
// figure drawn from the contents counts only the surer ones.
SiteContents ReadSiteContents(db::SiteDatabase& site, double min_confidence = 0.0);

}  // namespace littermap::heatmap
