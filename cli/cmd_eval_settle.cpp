// littermap eval settle BAG TRAJECTORY.tum [-o SETTLED.tum] [--json]
// How far a trajectory lies from the nearest one its scans agree with
// (reconstruct/scan_settling.hpp).

#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "cli/bag_scans.hpp"
#include "cli/cli_context.hpp"
#include "core/error.hpp"
#include "eval/trajectory_metrics.hpp"
#include "reconstruct/scan_settling.hpp"

namespace littermap::cli {
namespace {

struct SettleArguments {
  std::string bag;
  std::string trajectory;
  std::string output;
  std::string scan_topic = bag::RunTopics{}.scan;
  double max_time_difference_s = 0.02;
  bool json = false;
  reconstruct::ScanSettlingOptions options;
};

// The scans of the bag placed with the trajectory's poses and aligned; warnings for what was
// left out.
reconstruct::ScanSettling Settle(const SettleArguments& arguments, CliContext& context) {
  const auto [T_base_laser, scans] = ReadBagScans(arguments.bag, arguments.scan_topic, context);
  std::vector<TimestampNs> stamps_ns;
  for (const LaserScan& scan : scans) stamps_ns.push_back(scan.stamp_ns);
  const std::vector<std::optional<PlanarPose>> poses = eval::PlanarPosesAt(
      bag::ReadTumTrajectory(arguments.trajectory), stamps_ns, arguments.max_time_difference_s);
  context.Status("aligning the scans from the poses of " + arguments.trajectory);
  reconstruct::ScanSettling settling;
  try {
    settling = reconstruct::SettleOnScans(scans, poses, T_base_laser, arguments.options);
  } catch (const BadInputError& error) {
    throw BadInputError(arguments.trajectory + ": " + error.what());
  }
  context.FinishProgress();
  if (settling.scans_posed < settling.scans) {
    context.Warn(std::to_string(settling.scans - settling.scans_posed) + " of " +
                 std::to_string(settling.scans) + " scans have no pose in " + arguments.trajectory +
                 " close enough in time, and are left out");
  }
  if (settling.scans_placed < settling.scans_posed) {
    context.Warn(std::to_string(settling.scans_posed - settling.scans_placed) + " of " +
                 std::to_string(settling.scans) +
                 " scans have too few valid echoes, and are left out");
  }
  if (!settling.alignment.usable) {
    context.Warn("the scan alignment stopped early (" + std::to_string(settling.alignment.rounds) +
                 " usable rounds); the settled poses are those of its last usable round");
  }
  return settling;
}

void RunSettle(const SettleArguments& arguments, CliContext& context) {
  arguments.options.Validate();
  if (!(arguments.max_time_difference_s >= 0)) {
    throw UsageError("--max-time-difference must be >= 0");
  }
  const std::filesystem::path output = arguments.output;
  if (!output.empty() &&
      !std::filesystem::is_directory(output.parent_path().empty() ? std::filesystem::path(".")
                                                                  : output.parent_path())) {
    throw UsageError(arguments.output + ": its directory does not exist");
  }
  const reconstruct::ScanSettling settling = Settle(arguments, context);
  const std::vector<StampedPose> settled = StampedPosesFromPlanar(settling.settled);
  const eval::TrajectoryMetrics moved =
      eval::EvaluateTrajectory(StampedPosesFromPlanar(settling.given), settled, {});
  if (!output.empty()) bag::WriteTumTrajectory(output, settled);
  if (arguments.json) {
    nlohmann::ordered_json json;
    json["scans"] = settling.scans;
    json["scans_posed"] = settling.scans_posed;
    json["scans_placed"] = settling.scans_placed;
    json["scans_aligned"] = settling.settled.size();
    json["scan_pairs"] = settling.alignment.pairs_matched;
    json["point_pairs"] = settling.alignment.correspondences;
    json["usable"] = settling.alignment.usable;
    json["ate_rmse_m"] = moved.ate_rmse_m;
    json["ate_max_m"] = moved.ate_max_m;
    json["rpe_trans_mean_m"] = moved.rpe_trans_mean_m;
    json["rpe_rot_mean_deg"] = moved.rpe_rot_mean_deg;
    std::printf("%s\n", json.dump(2).c_str());
    return;
  }
  std::printf("scans aligned      %zu of %zu (one per %.2f m or %.0f deg of motion)\n",
              settling.settled.size(), settling.scans, arguments.options.frame_spacing_m,
              arguments.options.frame_spacing_rad * 180 / std::numbers::pi);
  std::printf("pairs              %zu scan pairs, %zu point pairs\n",
              settling.alignment.pairs_matched, settling.alignment.correspondences);
  std::printf("moved to agree with its scans:\n");
  std::printf("ATE RMSE           %.4f m (max %.4f m)\n", moved.ate_rmse_m, moved.ate_max_m);
  std::printf("RPE translation    %.4f m mean over %zu pairs 1 m apart\n", moved.rpe_trans_mean_m,
              moved.rpe_pairs);
  std::printf("RPE rotation       %.3f deg mean\n", moved.rpe_rot_mean_deg);
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
      ->check(CLI::ExistingPath);
  settle->add_option("TRAJECTORY", arguments->trajectory, "Trajectory of base_link (TUM format)")
      ->required()
      ->check(CLI::ExistingFile);
  settle->add_option("-o,--output", arguments->output,
                     "Write the settled poses (TUM format) of the scans aligned (one per 0.5 m or "
                     "17 deg of motion)");
  settle->add_option("--scan-topic", arguments->scan_topic, "LaserScan topic")
      ->capture_default_str();
  settle
      ->add_option("--max-time-difference", arguments->max_time_difference_s,
                   "Largest stamp difference between a scan and its pose, seconds")
      ->capture_default_str();
  settle->add_flag("--json", arguments->json,
                   "JSON output (ate_rmse_m, rpe_trans_mean_m, rpe_rot_mean_deg of the move, "
                   "scans_aligned, ...)");
  settle->callback([arguments, &context] {
    context.run = [arguments, &context] { RunSettle(*arguments, context); };
  });
}

}  // namespace littermap::cli
