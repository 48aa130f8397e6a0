// littermap simulate WORLD.yaml -o BAG --truth TRUTH_DIR [--seed N] [--run-seed N]
//                   [--route NAME] [--duration S] [--start-time DATE] [--litter-day N]
//                   [--contact-sheet FILE.png]
// A survey run in a procedural park: a run bag like a real capture plus its ground truth.

#include <cstdio>
#include <memory>

#include "bag/contact_sheet.hpp"
#include "cli/date_argument.hpp"
#include "cli/simulate_run.hpp"
#include "cli/truth_map.hpp"
#include "core/error.hpp"
#include "sim/recorder.hpp"
#include "sim/world_spec.hpp"

namespace littermap::cli {

void RunSimulate(const SimulateRequest& request, CliContext& context) {
  const sim::WorldSpec spec = sim::LoadWorldSpec(request.world);
  sim::SimRecordOptions options;
  options.seed = request.seed;
  options.run_seed = request.run_seed;
  options.route = request.route;
  options.start_time_s = ParseDateArgument(request.start_time, "--start-time");
  options.litter_day = request.litter_day;
  if (request.duration_s) {
    if (!(*request.duration_s > 0)) throw UsageError("--duration: must be positive");
    options.max_duration_s = *request.duration_s;
  }
  const sim::SimRecordResult result =
      sim::RecordSimulation(spec, request.bag, request.truth, options, context.Progress());
  context.FinishProgress();
  std::printf(
      "wrote %s: %llu scans (%s), %llu odometry, %llu imu, %llu rgb-d frames, %.1f s, %.1f m%s "
      "(seed %llu, run seed %llu%s%s, %.1f frames/s)\n",
      request.bag.c_str(), static_cast<unsigned long long>(result.scans), result.laser.c_str(),
      static_cast<unsigned long long>(result.odometry), static_cast<unsigned long long>(result.imu),
      static_cast<unsigned long long>(result.frames), result.duration_s, result.distance_m,
      result.route_completed ? "" : " (route cut short)",
      static_cast<unsigned long long>(result.seed),
      static_cast<unsigned long long>(result.run_seed), request.route.empty() ? "" : ", route ",
      request.route.c_str(),
      result.simulate_s > 0 ? static_cast<double>(result.frames) / result.simulate_s : 0.0);
  if (!request.truth.empty()) {
    WriteTruthMap(sim::Simulation(sim::RunSpec(spec, options), {options.max_duration_s}),
                  request.truth);
    std::printf(
        "wrote %s: %llu litter, %llu natural look-alikes, %llu primitives, %llu masks, "
        "map.pgm\n",
        request.truth.c_str(), static_cast<unsigned long long>(result.litter),
        static_cast<unsigned long long>(result.natural),
        static_cast<unsigned long long>(result.objects),
        static_cast<unsigned long long>(result.masks));
  }
  if (!request.contact_sheet.empty()) {
    const bag::ContactSheetResult sheet =
        bag::WriteContactSheet(request.bag, request.contact_sheet);
    std::printf("wrote %s: %d frames (colour | depth | laser), %dx%d px\n",
                request.contact_sheet.c_str(), sheet.rows, sheet.width_px, sheet.height_px);
  }
}

void RegisterSimulateCommand(CLI::App& app, CliContext& context) {
  auto request = std::make_shared<SimulateRequest>();
  CLI::App* simulate = context.AddCommand(
      app, "simulate",
      "Simulate a survey run in a procedural park: a run bag (/scan, /odom, /imu, RGB-D camera, "
      "/tf_static) and its ground truth");
  simulate->add_option("WORLD", request->world, "World description (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  simulate->add_option("-o,--output", request->bag, "Bag directory to create")->required();
  simulate
      ->add_option("--truth", request->truth,
                   "Directory for trajectory.tum, litter.csv, natural.csv, world.json, masks/")
      ->required();
  simulate
      ->add_option("--seed", request->seed,
                   "Random seed of the world and the run (overrides the world's seed)")
      ->check(CLI::NonNegativeNumber);
  simulate
      ->add_option("--run-seed", request->run_seed,
                   "Random seed of sensor noise, odometry drift and timing only: the same "
                   "park, another run")
      ->check(CLI::NonNegativeNumber);
  simulate->add_option("--route", request->route,
                       "Drive this route of the world's `routes` instead of `route`");
  simulate->add_option("--duration", request->duration_s,
                       "Stop after this many seconds of the route");
  simulate->add_option("--start-time", request->start_time,
                       "When the run starts, YYYY-MM-DD[THH:MM[:SS]] UTC (default: the world's "
                       "start_time_s); a site's runs are told apart and ordered by it");
  simulate
      ->add_option("--litter-day", request->litter_day,
                   "Survey the park on this day: the world's litter changed day by day "
                   "(litter.daily_pickup_fraction picked up, litter.daily_new dropped); at most "
                   "3650")
      ->check(CLI::Range(0, sim::kMaxLitterDay));
  simulate->add_option("--contact-sheet", request->contact_sheet,
                       "Also write a PNG of sampled colour, depth and laser frames of the bag");
  simulate->callback([request, &context] {
    context.run = [request, &context] { RunSimulate(*request, context); };
  });
}

}  // namespace littermap::cli
