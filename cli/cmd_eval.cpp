// littermap eval trajectory (eval/trajectory_metrics.hpp); `eval` itself, the others' parent

#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "eval/trajectory_metrics.hpp"

namespace littermap::cli {
namespace {

struct TrajectoryArguments {
  std::string estimate;
  std::string reference;
  bool json = false;
  eval::TrajectoryMetricsOptions options;
};

void RunTrajectory(const TrajectoryArguments& arguments) {
  const eval::TrajectoryMetrics metrics =
      eval::EvaluateTrajectory(arguments.estimate, arguments.reference, arguments.options);
  std::printf("%s\n", arguments.json ? eval::ToJson(metrics).c_str()
                                     : eval::ToText(metrics, arguments.options).c_str());
}

}  // namespace

void RegisterEvalCommands(CLI::App& app, CliContext& context) {
  CLI::App* eval_command = context.AddCommand(
      app, "eval", "Evaluate trajectories and litter detections against ground truth");
  eval_command->require_subcommand(1);
  auto arguments = std::make_shared<TrajectoryArguments>();
  CLI::App* trajectory = context.AddCommand(
      *eval_command, "trajectory",
      "ATE RMSE after rigid (Horn) alignment and RPE over pairs 1 m apart, as the TUM RGB-D "
      "benchmark scripts compute them");
  trajectory->add_option("EST", arguments->estimate, "Estimated trajectory (TUM format)")
      ->required()
      ->check(ExistingInput(InputKind::kFile));
  trajectory->add_option("REF", arguments->reference, "Reference trajectory (TUM format)")
      ->required()
      ->check(ExistingInput(InputKind::kFile));
  trajectory->add_flag("--json", arguments->json,
                       "JSON output (ate_rmse_m, rpe_trans_mean_m, rpe_rot_mean_deg, ...)");
  trajectory
      ->add_option("--max-time-difference", arguments->options.max_time_difference_s,
                   "Largest stamp difference of an associated pair, seconds")
      ->capture_default_str()
      ->check(FiniteRange(1e-6, 3600));
  trajectory
      ->add_option("--rpe-delta", arguments->options.rpe_delta_m,
                   "Distance travelled between the poses of an RPE pair, metres")
      ->capture_default_str()
      ->check(FiniteRange(0.01, 1e5));
  trajectory->callback(
      [arguments, &context] { context.run = [arguments] { RunTrajectory(*arguments); }; });
}

}  // namespace littermap::cli
