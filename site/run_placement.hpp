#pragma once
// Where a run's map frame sits in the site frame, before it is ingested: placed by hand, or
// matched from where it starts (the dock, or a given initial pose) onto the site map, or, for
// the first run with a map, the site frame itself (its map becomes the site map).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/planar_pose.hpp"
#include "db/site_database.hpp"
#include "reconstruct/map_registration.hpp"
#include "site/run_ingest.hpp"

namespace littermap::site {

struct PlacementOptions {
  std::optional<PlanarPose> initial;    // where the run starts in the site; none: the dock
  std::optional<PlanarPose> transform;  // place the run here by hand, no matching
  reconstruct::MapRegistrationOptions registration;
};

// Sets run->T_site_run, registration_quality and (first map) site_map from the run's
// map_yaml (none: placed where it starts). `notes` gets a line on what was done. Throws
// BadInputError naming the map and the site when the run's map does not match the site map.
void PlaceRun(db::SiteDatabase& site, const std::filesystem::path& map_yaml,
              const PlacementOptions& options, RunInput* run, std::vector<std::string>* notes);

}  // namespace littermap::site
