// littermap eval map (reconstruct/trajectory_map_sharpness.hpp)

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "reconstruct/trajectory_map_sharpness.hpp"

namespace littermap::cli {
namespace {

struct MapArguments {
  std::string bag;
  std::vector<std::string> trajectories;
  bool json = false;
  reconstruct::TrajectoryMapsOptions options;
};

void RunMap(const MapArguments& arguments, CliContext& context) {
  const std::vector<eval::MapSharpness> maps = reconstruct::MeasureTrajectoryMaps(
      arguments.bag, arguments.trajectories, arguments.options,
      [&context](const Progress& step) { context.Status(std::string(step.task)); },
      [&context](const std::string& warning) { context.Warn(warning); });
  context.FinishProgress();
  const auto& names = arguments.trajectories;
  std::printf("%s\n", arguments.json ? eval::ToJson(names, maps, arguments.options.map).c_str()
                                     : eval::ToText(names, maps, arguments.options.map).c_str());
}

}  // namespace

void RegisterEvalMapCommand(CLI::App& app, CliContext& context) {
  CLI::App& eval_command = *app.get_subcommand("eval");
  auto arguments = std::make_shared<MapArguments>();
  CLI::App* map = context.AddCommand(
      eval_command, "map",
      "How sharp a map each trajectory draws from the bag's scans: the number of grid cells their "
      "echoes occupy (fewer is sharper; needs no reference, so it also judges one)");
  map->add_option("BAG", arguments->bag, "Run bag with the laser scans")
      ->required()
      ->check(ExistingInput(InputKind::kFileOrFolder));
  map->add_option("TRAJECTORY", arguments->trajectories,
                  "Trajectories of base_link (TUM format), e.g. RUN_DIR/trajectory.tum and a "
                  "reference; the table compares each with the first")
      ->required()
      ->check(ExistingInput(InputKind::kFile));
  map->add_option("--scan-topic", arguments->options.scan_topic, "LaserScan topic")
      ->capture_default_str();
  map->add_option("--cell-size", arguments->options.map.cell_size_m, "Grid cell size, metres")
      ->capture_default_str()
      ->check(FiniteRange(kMinCellSizeM / 5, kMaxCellSizeM));
  map->add_option("--max-range", arguments->options.map.max_range_m,
                  "Echoes further than this are not drawn, metres")
      ->capture_default_str()
      ->check(FiniteRange(0.1, 1000));
  map->add_option("--max-time-difference", arguments->options.map.max_time_difference_s,
                  "Largest stamp difference between a scan and its pose, seconds")
      ->capture_default_str()
      ->check(FiniteRange(0, 3600));
  map->add_flag("--json", arguments->json,
                "JSON output (per trajectory: occupied_cells, echoes_drawn, scans_drawn, scans)");
  map->callback([arguments, &context] {
    context.run = [arguments, &context] { RunMap(*arguments, context); };
  });
}

}  // namespace littermap::cli
