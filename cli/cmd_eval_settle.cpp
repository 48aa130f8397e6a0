// littermap eval settle (reconstruct/trajectory_settling.hpp)

#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_context.hpp"
#include "cli/option_checks.hpp"
#include "core/error.hpp"
#include "reconstruct/trajectory_settling.hpp"

namespace littermap::cli {
namespace {

struct SettleArguments {
  std::string bag;
  std::string trajectory;
  bool json = false;
  reconstruct::TrajectorySettlingOptions options;
};

void RunSettle(const SettleArguments& arguments, CliContext& context) {
  if (!(arguments.options.max_time_difference_s >= 0)) {
    throw UsageError("--max-time-difference must be >= 0");
  }
  const reconstruct::TrajectorySettling result = reconstruct::SettleTrajectory(
      arguments.bag, arguments.trajectory, arguments.options,
      [&context](const Progress& step) { context.Status(std::string(step.task)); },
      [&context](const std::string& warning) { context.Warn(warning); });
  context.FinishProgress();
  std::printf("%s\n", arguments.json ? reconstruct::ToJson(result).c_str()
                                     : reconstruct::ToText(result, arguments.options).c_str());
}

}  // namespace

void RegisterEvalSettleCommand(CLI::App& app, CliContext& context) {
  CLI::App& eval_command = *app.get_subcommand("eval");
  auto arguments = std::make_shared<SettleArguments>();
  CLI::App* settle = context.AddCommand(
      eval_command, "settle",
      "How far a trajectory lies from the nearest one its own scans agree with: the scans are "
      "aligned against each other from its poses (reconstruct's final scan alignment), and the "
      "move is reported as ATE and RPE (needs no reference, so it also judges one)");
  settle->add_option("BAG", arguments->bag, "Run bag with the laser scans")
      ->required()
      ->check(ExistingInput(InputKind::kFileOrFolder));
  settle->add_option("TRAJECTORY", arguments->trajectory, "Trajectory of base_link (TUM format)")
      ->required()
      ->check(ExistingInput(InputKind::kFile));
  settle->add_option("-o,--output", arguments->options.output,
                     "Write the settled poses (TUM format) of the scans aligned (one per 0.5 m or "
                     "17 deg of motion)");
  settle->add_option("--scan-topic", arguments->options.scan_topic, "LaserScan topic")
      ->capture_default_str();
  settle
      ->add_option("--max-time-difference", arguments->options.max_time_difference_s,
                   "Largest stamp difference between a scan and its pose, seconds")
      ->capture_default_str()
      ->check(FiniteRange(0, 3600));
  settle->add_flag("--json", arguments->json,
                   "JSON output (ate_rmse_m, rpe_trans_mean_m, rpe_rot_mean_deg of the move, "
                   "scans_aligned, ...)");
  settle->callback([arguments, &context] {
    context.run = [arguments, &context] { RunSettle(*arguments, context); };
  });
}

}  // namespace littermap::cli
