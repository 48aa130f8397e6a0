// littermap ingest SITE.gpkg RUN_DIR: adds a reconstructed run (RUN_DIR/trajectory.tum and
// RUN_DIR/items.csv from `detect`) to a site database. Idempotent. A simulator TRUTH_DIR
// (trajectory.tum, litter.csv) is accepted too: its truth stands in for detected items, e.g. to
// compare a detected run with what was really there.
// Registration: the first run with a map (RUN_DIR/map.yaml) defines the site map; later runs
// start from the dock (the site origin, or --initial) and are placed by matching their map to
// the site map, refused when the match is poor; --transform places a run by hand.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "cli/cli_context.hpp"
#include "cli/ingest_command.hpp"
#include "core/error.hpp"
#include "core/map_server_grey.hpp"
#include "core/pose3.hpp"
#include "db/site_database.hpp"
#include "heatmap/run_ingest.hpp"
#include "reconstruct/map_registration.hpp"
#include "reconstruct/occupancy_map_file.hpp"

namespace littermap::cli {
namespace {

struct IngestArguments {
  std::string site;
  std::string run_dir;
  std::string name;
  std::vector<double> initial;    // x y yaw_deg: where the run starts in the site (the dock)
  std::vector<double> transform;  // x y yaw_deg: place the run by hand, no matching
  reconstruct::MapRegistrationOptions registration;
  heatmap::IngestOptions options;
};

PlanarPose PoseArgument(const std::vector<double>& values) {
  if (values.empty()) return {};
  return {values[0], values[1], values[2] * std::numbers::pi / 180};
}

// Where the run's frame sits in the site: by hand, by matching its map onto the site map, or
// (first run, no map) the site frame itself.
void PlaceRun(const IngestArguments& arguments, db::SiteDatabase& site, heatmap::RunInput* run) {
  const std::filesystem::path map_yaml = std::filesystem::path(arguments.run_dir) / "map.yaml";
  const bool by_hand = !arguments.transform.empty();
  run->T_site_run = by_hand ? PoseArgument(arguments.transform) : PoseArgument(arguments.initial);
  if (!std::filesystem::exists(map_yaml)) {
    if (!by_hand) {
      std::printf("%s: no map.yaml to match; the run is placed where it starts (%s)\n",
                  arguments.run_dir.c_str(),
                  arguments.initial.empty() ? "the dock, the site origin" : "--initial");
    }
    return;
  }
  const OccupancyImage run_map = reconstruct::ReadOccupancyMap(map_yaml);
  const std::optional<db::SiteMapRecord> site_map = site.SiteMap();
  if (!site_map) {
    run->site_map = db::SiteMapRecord{0, run_map, run->T_site_run};
    std::printf("The run's map becomes the site map\n");
    return;
  }
  if (by_hand) return;
  reconstruct::Points2 site_points = reconstruct::OccupiedCellCentres(site_map->image);
  for (Eigen::Vector2d& p : site_points) p = reconstruct::Transform(site_map->T_site_map, p);
  const reconstruct::MapRegistrationResult registration = reconstruct::RegisterMap(
      site_points, reconstruct::OccupiedCellCentres(run_map), run->T_site_run,
      arguments.registration, [&](const Eigen::Vector2d& p) {
        const std::optional<std::uint8_t> grey = site_map->GreyAt({p.x(), p.y()});
        return grey && *grey != map_grey::kUnknown;
      });
  if (!registration.registered) {
    char detail[200];
    std::snprintf(detail, sizeof detail,
                  " within %.1f m of where it starts (matching ratio %.2f, needs %.2f, over %zu "
                  "points where the site map knows the ground, needs %zu)",
                  arguments.registration.window_m, registration.matching_ratio,
                  arguments.registration.min_matching_ratio, registration.overlap_points,
                  arguments.registration.min_overlap_points);
    throw BadInputError(
        map_yaml.string() + ": the run's map does not match the site map of " + arguments.site +
        detail +
        ". If the run did not start at the dock give --initial X Y DEG near its start, or place "
        "it by hand with --transform X Y DEG");
  }
  run->T_site_run = registration.T_site_run;
  run->registration_quality = registration.matching_ratio;
  std::printf(
      "Registered onto the site map: x %.2f m, y %.2f m, yaw %.2f deg (matching ratio "
      "%.2f)\n",
      run->T_site_run.x_m, run->T_site_run.y_m, run->T_site_run.theta_rad * 180 / std::numbers::pi,
      registration.matching_ratio);
}

std::vector<PlanarPose> PlanarTrajectory(const std::vector<StampedPose>& poses) {
  std::vector<PlanarPose> planar;
  planar.reserve(poses.size());
  for (const StampedPose& pose : poses) {
    planar.push_back({pose.position_m.x(), pose.position_m.y(), YawOf(pose.orientation)});
  }
  return planar;
}

// Places the run (unless it is already in the site) and ingests it. If another process's run
// defined the site map in between, the run is placed again, now against that map.
heatmap::IngestResult PlaceAndIngest(const IngestArguments& arguments, db::SiteDatabase& site,
                                     const heatmap::RunInput& run_frame) {
  for (int attempt = 0;; ++attempt) {
    heatmap::RunInput run = run_frame;
    if (!site.FindRun(run.source_digest)) PlaceRun(arguments, site, &run);
    for (PlanarPose& pose : run.T_site_base) pose = Compose(run.T_site_run, pose);
    for (heatmap::RunItem& item : run.items) {
      const Eigen::Vector2d p =
          reconstruct::Transform(run.T_site_run, Eigen::Vector2d(item.xy.x, item.xy.y));
      item.xy = {p.x(), p.y()};
    }
    try {
      return heatmap::IngestRun(site, run, arguments.options);
    } catch (const heatmap::SiteMapDefinedMeanwhile&) {
      if (attempt > 0) throw;
    }
  }
}

// reconstruct's quality.json, checked to be JSON; empty when the run has none (a simulator truth
// directory).
std::string ReadQuality(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) return {};
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  if (!in || !nlohmann::json::accept(text.str())) {
    throw BadInputError(file.string() + ": not a JSON file (reconstruct writes it; rerun it)");
  }
  return text.str();
}

void RunIngest(IngestArguments arguments, CliContext& context) {
  const std::filesystem::path run_dir = arguments.run_dir;
  const RunDirectoryFiles files = FindRunDirectoryFiles(run_dir);
  if (files.simulator_truth) {
    arguments.options.drop_unobserved_items = true;
    context.Warn(files.items.string() +
                 ": no items.csv; using the simulator's truth as the run's items (only those "
                 "inside the camera coverage)");
  }
  db::SiteDatabase site = db::SiteDatabase::Open(arguments.site);
  const std::vector<StampedPose> poses = bag::ReadTumTrajectory(files.trajectory);
  heatmap::RunInput run;
  run.name = arguments.name.empty() ? std::filesystem::absolute(run_dir).filename().string()
                                    : arguments.name;
  run.source_digest = RunDigest(files);
  run.T_site_base = PlanarTrajectory(poses);
  if (!poses.empty()) {
    run.start_time_s = ToSeconds(poses.front().stamp_ns);
    run.end_time_s = ToSeconds(poses.back().stamp_ns);
  }
  run.items = heatmap::ReadRunItems(files.items);
  run.reconstruction_quality = ReadQuality(run_dir / "quality.json");
  const heatmap::IngestResult result = PlaceAndIngest(arguments, site, run);
  if (result.already_ingested) {
    std::printf("Run %s is already in %s as run %lld; nothing changed\n", run.name.c_str(),
                arguments.site.c_str(), static_cast<long long>(result.run_id));
    return;
  }
  std::printf(
      "Ingested run %lld '%s': %zu poses, %.1f m driven, %.0f m2 observed, %zu detections "
      "(%zu new items, %zu seen again",
      static_cast<long long>(result.run_id), run.name.c_str(), result.poses, result.length_m,
      result.observed_area_m2, result.detections, result.new_items, result.items_seen_again);
  if (arguments.options.drop_unobserved_items) {
    std::printf(", %zu outside the camera coverage skipped", result.items_unobserved);
  }
  std::printf(")\n");
}

}  // namespace

RunDirectoryFiles FindRunDirectoryFiles(const std::filesystem::path& run_dir) {
  RunDirectoryFiles files{run_dir / "trajectory.tum", run_dir / "items.csv", false};
  if (!std::filesystem::exists(files.items) && std::filesystem::exists(run_dir / "litter.csv")) {
    files.items = run_dir / "litter.csv";
    files.simulator_truth = true;
  }
  if (!std::filesystem::exists(files.items)) {
    throw BadInputError(run_dir.string() + ": no items.csv (run 'littermap detect' first)");
  }
  return files;
}

std::string RunDigest(const RunDirectoryFiles& files) {
  const std::filesystem::path digested[] = {files.trajectory, files.items};
  return heatmap::DigestFiles(digested);
}

void RegisterIngestCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<IngestArguments>();
  CLI::App* ingest =
      context.AddCommand(app, "ingest", "Add a reconstructed run to a site database");
  ingest->add_option("SITE", arguments->site, "Site database (SITE.gpkg)")->required();
  ingest
      ->add_option("RUN_DIR", arguments->run_dir, "Run directory with trajectory.tum and items.csv")
      ->required();
  ingest->add_option("--name", arguments->name, "Run name (default: the directory name)");
  ingest
      ->add_option("--initial", arguments->initial,
                   "Where the run starts in the site frame, X Y DEG (default: the dock, 0 0 0); "
                   "its map is matched from there")
      ->expected(3);
  ingest
      ->add_option("--transform", arguments->transform,
                   "Place the run's frame at X Y DEG in the site frame by hand, without matching")
      ->expected(3);
  ingest
      ->add_option("--search-window", arguments->registration.window_m,
                   "How far (m) from --initial the run's map is searched for on the site map")
      ->capture_default_str();
  ingest
      ->add_option("--min-matching-ratio", arguments->registration.min_matching_ratio,
                   "Share of the run's map that must land on the site map")
      ->capture_default_str();
  auto& options = arguments->options;
  ingest
      ->add_option("--same-item-radius", options.same_item_radius_m,
                   "An item of the same class this close (m) to a known one is that item")
      ->capture_default_str();
  ingest
      ->add_option("--detection-range", options.camera.max_detection_range_m,
                   "Camera detection range on the ground (m)")
      ->capture_default_str();
  ingest
      ->add_option("--camera-hfov", options.camera.horizontal_fov_deg,
                   "Camera horizontal field of view (deg)")
      ->capture_default_str();
  ingest
      ->add_option("--coverage-cell", options.coverage_cell_size_m,
                   "Cell size (m) of the stored camera coverage")
      ->capture_default_str();
  ingest->callback([arguments, &context] {
    context.run = [arguments, &context] { RunIngest(*arguments, context); };
  });
}

}  // namespace littermap::cli
