// littermap ingest SITE.gpkg RUN_DIR: adds a reconstructed run (trajectory.tum, items.csv from
// `detect`, map.yaml) or a simulator truth directory to a site database, placed by matching its
// map to the site map or by hand (site/run_directory_ingest.hpp, site/run_placement.hpp).

#include <cstdio>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "db/site_locator.hpp"
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
  const db::SiteLocator site = db::ParseSiteLocator(arguments.site);
  const site::RunDirectoryIngestResult result =
      site::IngestRunDirectory(site, arguments.run_dir, arguments.options);
  for (const std::string& warning : result.warnings) context.Warn(warning);
  std::printf("%s\n", site::IngestSummary(result, site.display).c_str());
}

}  // namespace

void RegisterIngestCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<IngestArguments>();
  CLI::App* ingest =
      context.AddCommand(app, "ingest", "Add a reconstructed run to a site database");
  ingest
      ->add_option("SITE", arguments->site,
                   "Site database: SITE.gpkg, or postgresql://[USER@HOST]/DB?site=NAME")
      ->required();
  ingest
      ->add_option("RUN_DIR", arguments->run_dir, "Run directory with trajectory.tum and items.csv")
      ->required();
  ingest->add_option(
      "--name", arguments->options.name,
      "Run name (default: the folder's name, or its parent's for a folder called run or bag); "
      "a name the site holds for other results is refused");
  ingest
      ->add_option("--initial", arguments->initial,
                   "Where the run starts in the site frame, X Y DEG (default: the dock, 0 0 0); "
                   "its map is matched from there")
      ->expected(3)
      ->check(FiniteRange(-kMaxSiteCoordinateM, kMaxSiteCoordinateM));
  ingest
      ->add_option("--transform", arguments->transform,
                   "Place the run's frame at X Y DEG in the site frame by hand, without matching")
      ->expected(3)
      ->check(FiniteRange(-kMaxSiteCoordinateM, kMaxSiteCoordinateM));
  ingest->option_defaults()->always_capture_default();  // shown in --help
  ingest
      ->add_option("--search-window", arguments->options.placement.registration.window_m,
                   "How far (m) from --initial the run's map is searched for on the site map")
      ->check(FiniteRange(0.1, 1000));
  ingest
      ->add_option("--min-matching-ratio",
                   arguments->options.placement.registration.min_matching_ratio,
                   "Share of the run's map that must land on the site map")
      ->check(FiniteRange(0, 1));
  auto& options = arguments->options.ingest;
  ingest
      ->add_option("--same-item-radius", options.same_item_radius_m,
                   "A detection this close (m) to a known item is that item, whatever its class")
      ->check(FiniteRange(0.01, 100));
  ingest
      ->add_option("--detection-range", options.camera.max_detection_range_m,
                   "Camera detection range on the ground (m)")
      ->check(FiniteRange(0.1, 100));
  ingest
      ->add_option("--camera-hfov", options.camera.horizontal_fov_deg,
                   "Camera horizontal field of view (deg)")
      ->check(FiniteRange(1, 179));
  ingest
      ->add_option("--coverage-cell", options.coverage_cell_size_m,
                   "Cell size (m) of the stored camera coverage")
      ->check(FiniteRange(kMinCellSizeM, kMaxCellSizeM));
  ingest->callback([arguments, &context] {
    context.run = [arguments, &context] { RunIngest(*arguments, context); };
  });
}

}  // namespace littermap::cli
