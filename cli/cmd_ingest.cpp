// littermap ingest SITE.gpkg RUN_DIR: adds a reconstructed run (RUN_DIR/trajectory.tum and
// RUN_DIR/items.csv) to a site database. Idempotent. Until the detect stage exists, the
// simulator's truth (RUN_DIR/litter.csv) stands in for items.csv.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "capture/tum_trajectory.hpp"
#include "cli/cli_context.hpp"
#include "core/error.hpp"
#include "db/site_database.hpp"
#include "heatmap/run_ingest.hpp"

namespace littermap::cli {
namespace {

struct IngestArguments {
  std::string site;
  std::string run_dir;
  std::string name;
  heatmap::IngestOptions options;
};

std::vector<PlanarPose> PlanarTrajectory(const std::vector<TumPose>& poses) {
  std::vector<PlanarPose> planar;
  planar.reserve(poses.size());
  for (const TumPose& pose : poses) {
    const Eigen::Quaterniond& q = pose.orientation;
    const double yaw = std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()),
                                  1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
    planar.push_back({pose.position_m.x(), pose.position_m.y(), yaw});
  }
  return planar;
}

void RunIngest(IngestArguments arguments, CliContext& context) {
  const std::filesystem::path run_dir = arguments.run_dir;
  const auto trajectory_file = run_dir / "trajectory.tum";
  auto items_file = run_dir / "items.csv";
  if (!std::filesystem::exists(items_file) && std::filesystem::exists(run_dir / "litter.csv")) {
    items_file = run_dir / "litter.csv";
    arguments.options.drop_unobserved_items = true;
    context.Warn(items_file.string() +
                 ": no items.csv; using the simulator's truth as the run's items (only those "
                 "inside the camera coverage)");
  }
  if (!std::filesystem::exists(items_file)) {
    throw BadInputError(run_dir.string() + ": no items.csv (run 'littermap detect' first)");
  }
  db::SiteDatabase site = db::SiteDatabase::Open(arguments.site);
  const std::vector<TumPose> poses = ReadTumTrajectory(trajectory_file);
  heatmap::RunInput run;
  run.name = arguments.name.empty() ? std::filesystem::absolute(run_dir).filename().string()
                                    : arguments.name;
  const std::filesystem::path files[] = {trajectory_file, items_file};
  run.source_digest = heatmap::DigestFiles(files);
  run.T_site_base = PlanarTrajectory(poses);
  if (!poses.empty()) {
    run.start_time_s = ToSeconds(poses.front().stamp_ns);
    run.end_time_s = ToSeconds(poses.back().stamp_ns);
  }
  run.items = heatmap::ReadRunItems(items_file);
  const heatmap::IngestResult result = heatmap::IngestRun(site, run, arguments.options);
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

void RegisterIngestCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<IngestArguments>();
  CLI::App* ingest =
      context.AddCommand(app, "ingest", "Add a reconstructed run to a site database");
  ingest->add_option("SITE", arguments->site, "Site database (SITE.gpkg)")->required();
  ingest
      ->add_option("RUN_DIR", arguments->run_dir, "Run directory with trajectory.tum and items.csv")
      ->required();
  ingest->add_option("--name", arguments->name, "Run name (default: the directory name)");
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
