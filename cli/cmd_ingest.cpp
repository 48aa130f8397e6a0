// littermap ingest SITE.gpkg RUN_DIR: adds a reconstructed run (RUN_DIR/trajectory.tum and
// RUN_DIR/items.csv from `detect`) to a site database. Idempotent. A simulator TRUTH_DIR
// (trajectory.tum, litter.csv) is accepted too: its truth stands in for detected items, e.g. to
// compare a detected run with what was really there.
// Registration: the first run with a map (RUN_DIR/map.yaml) defines the site map; later runs
// start from the dock (the site origin, or --initial) and are placed by matching their map to
// the site map, refused when the match is poor; --transform places a run by hand
// (site/run_directory_ingest.hpp).

#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_context.hpp"
#include "cli/run_stages.hpp"
#include "db/site_database.hpp"
#include "site/run_directory_ingest.hpp"

namespace littermap::cli {
namespace {

struct IngestArguments {
  std::string site;
  std::string run_dir;
  std::vector<double> initial;    // x y yaw_deg: where the run starts in the site (the dock)
  std::vector<double> transform;  // x y yaw_deg: place the run by hand, no matching
  site::RunDirectoryIngestOptions options;
};

std::optional<PlanarPose> PoseArgument(const std::vector<double>& values) {
  if (values.empty()) return std::nullopt;
  return PlanarPose{values[0], values[1], values[2] * std::numbers::pi / 180};
}

void RunIngest(IngestArguments arguments, CliContext& context) {
  arguments.options.placement.initial = PoseArgument(arguments.initial);
  arguments.options.placement.transform = PoseArgument(arguments.transform);
  db::SiteDatabase site = db::SiteDatabase::Open(arguments.site);
  const site::RunDirectoryIngestResult run =
      site::IngestRunDirectory(site, arguments.run_dir, arguments.options);
  for (const std::string& warning : run.warnings) context.Warn(warning);
  for (const std::string& note : run.notes) std::printf("%s\n", note.c_str());
  const site::IngestResult& result = run.ingest;
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
  if (run.simulator_truth) {
    std::printf(", %zu outside the camera coverage skipped", result.items_unobserved);
  }
  std::printf(")\n");
}

}  // namespace

void IngestStage(const std::filesystem::path& site, const std::filesystem::path& run_dir,
                 const std::string& name, CliContext& context) {
  IngestArguments arguments;
  arguments.site = site.string();
  arguments.run_dir = run_dir.string();
  arguments.options.name = name;
  RunIngest(std::move(arguments), context);
}

void RegisterIngestCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<IngestArguments>();
  CLI::App* ingest =
      context.AddCommand(app, "ingest", "Add a reconstructed run to a site database");
  ingest->add_option("SITE", arguments->site, "Site database (SITE.gpkg)")->required();
  ingest
      ->add_option("RUN_DIR", arguments->run_dir, "Run directory with trajectory.tum and items.csv")
      ->required();
  ingest->add_option("--name", arguments->options.name, "Run name (default: the directory name)");
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
      ->add_option("--search-window", arguments->options.placement.registration.window_m,
                   "How far (m) from --initial the run's map is searched for on the site map")
      ->capture_default_str();
  ingest
      ->add_option("--min-matching-ratio",
                   arguments->options.placement.registration.min_matching_ratio,
                   "Share of the run's map that must land on the site map")
      ->capture_default_str();
  auto& options = arguments->options.ingest;
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
