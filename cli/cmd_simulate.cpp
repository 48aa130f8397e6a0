// littermap simulate WORLD.yaml -o BAG --truth TRUTH_DIR [--seed N] [--duration S]
// A survey run in a procedural park: a run bag like a real capture plus its ground truth.

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "capture/sim_recorder.hpp"
#include "cli/cli_context.hpp"
#include "core/error.hpp"
#include "sim/world_spec.hpp"

namespace littermap::cli {
namespace {

struct SimulateArguments {
  std::string world;
  std::string bag;
  std::string truth;
  std::optional<std::uint64_t> seed;
  std::optional<double> duration_s;
};

void RunSimulate(const SimulateArguments& arguments, CliContext& context) {
  const sim::WorldSpec spec = sim::LoadWorldSpec(arguments.world);
  SimRecordOptions options;
  options.seed = arguments.seed;
  if (arguments.duration_s) {
    if (!(*arguments.duration_s > 0)) throw UsageError("--duration: must be positive");
    options.max_duration_s = *arguments.duration_s;
  }
  const SimRecordResult result =
      RecordSimulation(spec, arguments.bag, arguments.truth, options, context.Progress());
  context.FinishProgress();
  std::printf(
      "wrote %s: %llu scans (%s), %llu odometry, %llu imu, %.1f s, %.1f m%s (seed %llu, %.0f "
      "scans/s)\n",
      arguments.bag.c_str(), static_cast<unsigned long long>(result.scans), result.laser.c_str(),
      static_cast<unsigned long long>(result.odometry), static_cast<unsigned long long>(result.imu),
      result.duration_s, result.distance_m, result.route_completed ? "" : " (route cut short)",
      static_cast<unsigned long long>(result.seed),
      result.simulate_s > 0 ? static_cast<double>(result.scans) / result.simulate_s : 0.0);
  std::printf("wrote %s: %llu litter, %llu natural look-alikes, %llu primitives\n",
              arguments.truth.c_str(), static_cast<unsigned long long>(result.litter),
              static_cast<unsigned long long>(result.natural),
              static_cast<unsigned long long>(result.objects));
}

}  // namespace

void RegisterSimulateCommand(CLI::App& app, CliContext& context) {
  auto arguments = std::make_shared<SimulateArguments>();
  CLI::App* simulate = context.AddCommand(
      app, "simulate",
      "Simulate a survey run in a procedural park: a run bag (/scan, /odom, /imu, /tf_static) "
      "and its ground truth");
  simulate->add_option("WORLD", arguments->world, "World description (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  simulate->add_option("-o,--output", arguments->bag, "Bag directory to create")->required();
  simulate
      ->add_option("--truth", arguments->truth,
                   "Directory for trajectory.tum, litter.csv, natural.csv, world.json")
      ->required();
  simulate->add_option("--seed", arguments->seed, "Random seed (overrides the world's seed)");
  simulate->add_option("--duration", arguments->duration_s,
                       "Stop after this many seconds of the route");
  simulate->callback([arguments, &context] {
    context.run = [arguments, &context] { RunSimulate(*arguments, context); };
  });
}

}  // namespace littermap::cli
