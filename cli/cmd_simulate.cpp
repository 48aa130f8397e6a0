// littermap simulate WORLD.yaml -o BAG --truth TRUTH_DIR [--seed N] [--run-seed N]
//                   [--route NAME] [--duration S] [--start-time DATE] [--litter-day N]
//                   [--contact-sheet FILE.png]
// A survey run in a procedural park: a run bag like a real capture plus its ground truth.

#include <cstdio>
#include <memory>

#include "cli/option_checks.hpp"
#include "cli/simulate_run.hpp"
#include "core/utc_date.hpp"

namespace littermap::cli {

void RunSimulate(SimulateRequest request, CliContext& context) {
  const sim::WorldSpec spec = sim::LoadWorldSpec(request.world);
  request.options.record.start_time_s = ParseUtcDate(request.start_time, "--start-time");
  sim::SimulateRun(spec, request.bag, request.options, context.Progress(),
                   [&context](const std::string& line) {
                     context.FinishProgress();
                     std::printf("%s\n", line.c_str());
                   });
}

void RegisterSimulateCommand(CLI::App& app, CliContext& context) {
  auto request = std::make_shared<SimulateRequest>();
  sim::SimRecordOptions& record = request->options.record;
  CLI::App* simulate = context.AddCommand(
      app, "simulate",
      "Simulate a survey run in a procedural park: a run bag (/scan, /odom, /imu, RGB-D camera, "
      "/tf_static) and its ground truth");
  simulate->add_option("WORLD", request->world, "World description (YAML)")
      ->required()
      ->check(ExistingInput(InputKind::kFile));
  simulate->add_option("-o,--output", request->bag, "Bag directory to create")->required();
  simulate
      ->add_option("--truth", request->options.truth_dir,
                   "Directory for trajectory.tum, litter.csv, natural.csv, world.json, masks/")
      ->required();
  simulate->add_flag("--force", record.force_truth,
                     "Write the truth into a --truth folder that holds files littermap does not "
                     "write there");
  simulate
      ->add_option("--seed", record.seed,
                   "Random seed of the world and the run (overrides the world's seed)")
      ->check(Seed());
  simulate
      ->add_option("--run-seed", record.run_seed,
                   "Random seed of sensor noise, odometry drift and timing only: the same "
                   "park, another run")
      ->check(Seed());
  simulate->add_option("--route", record.route,
                       "Drive this route of the world's `routes` instead of `route`");
  simulate
      ->add_option("--duration", request->options.duration_s,
                   "Stop after this many seconds of the route")
      ->check(FiniteRange(0.1, kMaxDurationS));
  simulate->add_option("--start-time", request->start_time,
                       "When the run starts, YYYY-MM-DD[THH:MM[:SS]] UTC (default: the world's "
                       "start_time_s); a site's runs are told apart and ordered by it");
  simulate
      ->add_option("--litter-day", record.litter_day,
                   "Survey the park on this day: the world's litter changed day by day "
                   "(litter.daily_pickup_fraction picked up, litter.daily_new dropped); at most "
                   "3650")
      ->check(WholeNumber(0, sim::kMaxLitterDay));
  simulate
      ->add_option("--storage", record.bag.storage,
                   "Bag storage: sqlite3 (rosbag2's default before Iron) or mcap")
      ->check(CLI::IsMember({"sqlite3", "mcap"}))
      ->capture_default_str();
  simulate
      ->add_option("--contact-sheet", request->options.contact_sheet_png,
                   "Also write a PNG of sampled colour, depth and laser frames of the bag")
      ->check(FileExtension({".png", ".jpg"}));
  simulate->callback([request, &context] {
    context.run = [request, &context] { RunSimulate(*request, context); };
  });
}

}  // namespace littermap::cli
