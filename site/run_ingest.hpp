#pragma once
// Adds one reconstructed run to a site database: the run, its track (run_tracks), the ground
// its camera observed (coverage), its detections and the litter items they are. An item within
// same_item_radius_m of a known item is that item seen again (litter stays until picked up),
// whatever class this run's classifier gave it, so reports can tell new litter from old.
// Idempotent: a run whose inputs' digest is already stored changes nothing. Everything is written
// in one transaction.
//
// Registration (placing the run's map frame in the site frame) happens before: RunInput is in
// the site frame already and records the transform used.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/planar_pose.hpp"
#include "db/site_database.hpp"
#include "site/run_items.hpp"
#include "site/survey_effort.hpp"

namespace littermap::site {

struct IngestOptions {
  CameraFootprintOptions camera;
  double coverage_cell_size_m = 0.5;
  // Two runs' placements of one item differ by both runs' trajectory errors and the
  // registration's: up to ~0.5 m each on the sample park (see issue notes on SLAM accuracy).
  double same_item_radius_m = 0.75;
  // Keep only items inside the run's camera coverage: for the simulator's truth, which lists
  // every item of the world, seen or not.
  bool drop_unobserved_items = false;
};

struct RunInput {
  std::string name;
  std::string source_digest;
  double start_time_s = 0.0;
  double end_time_s = 0.0;
  std::vector<PlanarPose> T_site_base;  // in time order
  std::vector<RunItem> items;           // site frame
  PlanarPose T_site_run;                // how the run's map frame was placed in the site
  std::optional<double> registration_quality;
  std::optional<db::SiteMapRecord> site_map;  // the first run with a map defines the site map
  std::string reconstruction_quality;         // reconstruct's quality.json, if there is one
};

struct IngestResult {
  bool already_ingested = false;
  std::int64_t run_id = 0;
  std::size_t poses = 0;
  std::size_t detections = 0;
  std::size_t new_items = 0;
  std::size_t items_seen_again = 0;
  std::size_t items_unobserved = 0;  // dropped (drop_unobserved_items)
  double observed_area_m2 = 0.0;
  double length_m = 0.0;
};

// Thrown by IngestRun when the run was to define the site map but another process's run did so
// first (two first runs at once): place the run against that map, then ingest it again.
class SiteMapDefinedMeanwhile : public BadInputError {
 public:
  using BadInputError::BadInputError;
};

// Throws BadInputError when the run has fewer than two poses.
IngestResult IngestRun(db::SiteDatabase& site, const RunInput& run, const IngestOptions& options);

}  // namespace littermap::site
