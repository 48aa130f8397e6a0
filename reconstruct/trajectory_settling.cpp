#include "reconstruct/trajectory_settling.hpp"

#include <numbers>
#include <optional>

#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "eval/text_format.hpp"

namespace littermap::reconstruct {
namespace {

// What the settling left out, and an alignment that stopped early.
void WarnOf(const ScanSettling& s, const std::filesystem::path& trajectory,
            const WarningCallback& warn) {
  if (!warn) return;
  if (s.scans_posed < s.scans) {
    warn(std::to_string(s.scans - s.scans_posed) + " of " + std::to_string(s.scans) +
         " scans have no pose in " + trajectory.string() +
         " close enough in time, and are left out");
  }
  if (s.scans_placed < s.scans_posed) {
    warn(std::to_string(s.scans_posed - s.scans_placed) + " of " + std::to_string(s.scans) +
         " scans have too few valid echoes, and are left out");
  }
  if (!s.alignment.usable) {
    warn("the scan alignment stopped early (" + std::to_string(s.alignment.rounds) +
         " usable rounds); the settled poses are those of its last usable round");
  }
}

}  // namespace

void TrajectorySettlingOptions::Validate() const {
  settling.Validate();
  if (!(max_time_difference_s >= 0)) {
    throw UsageError("trajectory settling: max_time_difference_s must be >= 0");
  }
  if (!output.empty() &&
      !std::filesystem::is_directory(output.parent_path().empty() ? std::filesystem::path(".")
                                                                  : output.parent_path())) {
    throw UsageError(output.string() + ": its directory does not exist");
  }
}

TrajectorySettling SettleTrajectory(const std::filesystem::path& bag,
                                    const std::filesystem::path& trajectory,
                                    const TrajectorySettlingOptions& options,
                                    const ProgressCallback& progress, const WarningCallback& warn) {
  options.Validate();
  const BagScans scans = ReadBagScans(bag, options.scan_topic, progress, warn);
  std::vector<TimestampNs> stamps_ns;
  for (const LaserScan& scan : scans.scans) stamps_ns.push_back(scan.stamp_ns);
  const std::vector<std::optional<PlanarPose>> poses = eval::PlanarPosesAt(
      bag::ReadTumTrajectory(trajectory), stamps_ns, options.max_time_difference_s);
  const std::string aligning = "aligning the scans from the poses of " + trajectory.string();
  ReportProgress(progress, {aligning});
  TrajectorySettling result;
  try {
    result.settling = SettleOnScans(scans.scans, poses, scans.T_base_laser, options.settling);
  } catch (const BadInputError& error) {
    throw BadInputError(trajectory.string() + ": " + error.what());
  }
  WarnOf(result.settling, trajectory, warn);
  const std::vector<StampedPose> settled = StampedPosesFromPlanar(result.settling.settled);
  result.moved =
      eval::EvaluateTrajectory(StampedPosesFromPlanar(result.settling.given), settled, {});
  if (!options.output.empty()) bag::WriteTumTrajectory(options.output, settled);
  return result;
}

std::string ToJson(const TrajectorySettling& result) {
  const ScanSettling& s = result.settling;
  nlohmann::ordered_json json;
  json["scans"] = s.scans;
  json["scans_posed"] = s.scans_posed;
  json["scans_placed"] = s.scans_placed;
  json["scans_aligned"] = s.settled.size();
  json["scan_pairs"] = s.alignment.pairs_matched;
  json["point_pairs"] = s.alignment.correspondences;
  json["usable"] = s.alignment.usable;
  json["ate_rmse_m"] = result.moved.ate_rmse_m;
  json["ate_max_m"] = result.moved.ate_max_m;
  json["rpe_trans_mean_m"] = result.moved.rpe_trans_mean_m;
  json["rpe_rot_mean_deg"] = result.moved.rpe_rot_mean_deg;
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string ToText(const TrajectorySettling& result, const TrajectorySettlingOptions& options) {
  const ScanSettling& s = result.settling;
  const eval::TrajectoryMetrics& moved = result.moved;
  std::string text;
  eval::AppendFormat(text, "scans aligned      %zu of %zu (one per %.2f m or %.0f deg of motion)\n",
                     s.settled.size(), s.scans, options.settling.frame_spacing_m,
                     options.settling.frame_spacing_rad * 180 / std::numbers::pi);
  eval::AppendFormat(text, "pairs              %zu scan pairs, %zu point pairs\n",
                     s.alignment.pairs_matched, s.alignment.correspondences);
  eval::AppendFormat(text, "moved to agree with its scans:\n");
  eval::AppendFormat(text, "ATE RMSE           %.4f m (max %.4f m)\n", moved.ate_rmse_m,
                     moved.ate_max_m);
  eval::AppendFormat(text, "RPE translation    %.4f m mean over %zu pairs 1 m apart\n",
                     moved.rpe_trans_mean_m, moved.rpe_pairs);
  eval::AppendFormat(text, "RPE rotation       %.3f deg mean\n", moved.rpe_rot_mean_deg);
  text.pop_back();  // the caller ends the last line, as after ToJson
  return text;
}

}  // namespace littermap::reconstruct
