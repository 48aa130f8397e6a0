// littermap eval map BAG TRAJECTORY.tum... [--cell-size M] [--max-range M] [--json]
// How sharp a map each trajectory draws from the bag's scans (eval/map_sharpness.hpp).

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bag/tum_trajectory.hpp"
#include "cli/bag_scans.hpp"
#include "cli/cli_context.hpp"
#include "core/error.hpp"
#include "eval/map_sharpness.hpp"

namespace littermap::cli {
namespace {

struct MapArguments {
  std::string bag;
  std::vector<std::string> trajectories;
  std::string scan_topic = bag::RunTopics{}.scan;
  bool json = false;
  eval::MapSharpnessOptions options;
};

void RunMap(const MapArguments& arguments, CliContext& context) {
  arguments.options.Validate();
  const auto [T_base_laser, scans] = ReadBagScans(arguments.bag, arguments.scan_topic, context);
  std::vector<eval::MapSharpness> results;
  for (const std::string& path : arguments.trajectories) {
    context.Status("drawing the scans with " + path);
    const std::vector<StampedPose> trajectory = bag::ReadTumTrajectory(path);
    eval::MapSharpness sharpness;
    try {
      sharpness = eval::MeasureMapSharpness(scans, T_base_laser, trajectory, arguments.options);
    } catch (const BadInputError& error) {
      throw BadInputError(path + ": " + error.what());
    }
    if (sharpness.scans_drawn < sharpness.scans) {
      char within[64];
      std::snprintf(within, sizeof within, "%g s", arguments.options.max_time_difference_s);
      context.Warn(path + ": " + std::to_string(sharpness.scans - sharpness.scans_drawn) + " of " +
                   std::to_string(sharpness.scans) + " scans have no pose within " + within +
                   " and are not drawn; counts of trajectories that draw different scans do "
                   "not compare");
    }
    results.push_back(sharpness);
  }
  context.FinishProgress();
  if (arguments.json) {
    std::printf("%s\n", eval::ToJson(arguments.trajectories, results, arguments.options).c_str());
    return;
  }
  std::printf("occupied %.0f cm cells of the echoes within %.1f m (fewer: sharper map)\n",
              100 * arguments.options.cell_size_m, arguments.options.max_range_m);
  std::printf("%12s %9s %12s %12s  %s\n", "cells", "vs first", "echoes", "scans", "trajectory");
  for (std::size_t i = 0; i < results.size(); ++i) {
    std::printf("%12zu %8.1f%% %12zu %5zu/%-6zu  %s\n", results[i].occupied_cells,
                100.0 * static_cast<double>(results[i].occupied_cells) /
                    static_cast<double>(results.front().occupied_cells),
                results[i].echoes_drawn, results[i].scans_drawn, results[i].scans,
                arguments.trajectories[i].c_str());
  }
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
      ->check(CLI::ExistingPath);
  map->add_option("TRAJECTORY", arguments->trajectories,
                  "Trajectories of base_link (TUM format), e.g. RUN_DIR/trajectory.tum and a "
                  "reference; the table compares each with the first")
      ->required()
      ->check(CLI::ExistingFile);
  map->add_option("--scan-topic", arguments->scan_topic, "LaserScan topic")->capture_default_str();
  map->add_option("--cell-size", arguments->options.cell_size_m, "Grid cell size, metres")
      ->capture_default_str();
  map->add_option("--max-range", arguments->options.max_range_m,
                  "Echoes further than this are not drawn, metres")
      ->capture_default_str();
  map->add_option("--max-time-difference", arguments->options.max_time_difference_s,
                  "Largest stamp difference between a scan and its pose, seconds")
      ->capture_default_str();
  map->add_flag("--json", arguments->json,
                "JSON output (per trajectory: occupied_cells, echoes_drawn, scans_drawn, scans)");
  map->callback([arguments, &context] {
    context.run = [arguments, &context] { RunMap(*arguments, context); };
  });
}

}  // namespace littermap::cli
