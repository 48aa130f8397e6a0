#include "site/run_placement.hpp"

#include <cstdio>
#include <numbers>

#include "core/error.hpp"
#include "core/map_server_grey.hpp"
#include "reconstruct/occupancy_map_file.hpp"

namespace littermap::site {

void PlaceRun(db::SiteDatabase& site, const std::filesystem::path& map_yaml,
              const PlacementOptions& options, RunInput* run, std::vector<std::string>* notes) {
  const bool by_hand = options.transform.has_value();
  run->T_site_run = by_hand ? *options.transform : options.initial.value_or(PlanarPose{});
  if (!std::filesystem::exists(map_yaml)) {
    if (!by_hand) {
      notes->push_back(map_yaml.parent_path().string() +
                       ": no map.yaml to match; the run is placed where it starts (" +
                       (options.initial ? "--initial" : "the dock, the site origin") + ")");
    }
    return;
  }
  const OccupancyImage run_map = reconstruct::ReadOccupancyMap(map_yaml);
  const std::optional<db::SiteMapRecord> site_map = site.SiteMap();
  if (!site_map) {
    run->site_map = db::SiteMapRecord{0, run_map, run->T_site_run};
    notes->push_back("The run's map becomes the site map");
    return;
  }
  if (by_hand) return;
  reconstruct::Points2 site_points = reconstruct::OccupiedCellCentres(site_map->image);
  for (Eigen::Vector2d& p : site_points) p = reconstruct::Transform(site_map->T_site_map, p);
  const reconstruct::MapRegistrationResult registration = reconstruct::RegisterMap(
      site_points, reconstruct::OccupiedCellCentres(run_map), run->T_site_run, options.registration,
      [&](const Eigen::Vector2d& p) {
        const std::optional<std::uint8_t> grey = site_map->GreyAt({p.x(), p.y()});
        return grey && *grey != map_grey::kUnknown;
      });
  if (!registration.registered) {
    char detail[200];
    std::snprintf(detail, sizeof detail,
                  " within %.1f m of where it starts (matching ratio %.2f, needs %.2f, over %zu "
                  "points where the site map knows the ground, needs %zu)",
                  options.registration.window_m, registration.matching_ratio,
                  options.registration.min_matching_ratio, registration.overlap_points,
                  options.registration.min_overlap_points);
    throw BadInputError(
        map_yaml.string() + ": the run's map does not match the site map of " + site.name() +
        detail +
        ". If the run did not start at the dock give --initial X Y DEG near its start, or place "
        "it by hand with --transform X Y DEG");
  }
  run->T_site_run = registration.T_site_run;
  run->registration_quality = registration.matching_ratio;
  char note[160];
  std::snprintf(note, sizeof note,
                "Registered onto the site map: x %.2f m, y %.2f m, yaw %.2f deg (matching ratio "
                "%.2f)",
                run->T_site_run.x_m, run->T_site_run.y_m,
                run->T_site_run.theta_rad * 180 / std::numbers::pi, registration.matching_ratio);
  notes->push_back(note);
}

}  // namespace littermap::site
