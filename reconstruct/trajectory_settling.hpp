#pragma once
// A trajectory file settled on a bag's scans (scan_settling.hpp), as `littermap eval settle` runs
// it: the scans placed with the trajectory's poses and aligned against each other, and how far
// the trajectory moved to agree with them, as ATE and RPE of its poses against the settled ones.

#include <filesystem>
#include <string>
#include <vector>

#include "bag/topics.hpp"
#include "core/progress.hpp"
#include "eval/trajectory_metrics.hpp"
#include "reconstruct/bag_scans.hpp"
#include "reconstruct/scan_settling.hpp"

namespace littermap::reconstruct {

struct TrajectorySettlingOptions {
  std::string scan_topic = bag::RunTopics{}.scan;
  double max_time_difference_s = 0.02;  // a scan without a pose this close is left out
  std::filesystem::path output;         // when set, the settled poses are written there (TUM)
  ScanSettlingOptions settling;
  void Validate() const;  // throws UsageError, also for an output in a missing directory
};

struct TrajectorySettling {
  ScanSettling settling;
  eval::TrajectoryMetrics moved;  // the given poses of the scans aligned against the settled
};

// `progress` is told each step as it starts (a task without counts: reading the scans, aligning
// them); `warn` hears of the bag's missing extrinsic, of scans left out and of an alignment that
// stopped early. Throws UsageError for invalid options, BadInputError naming the bag and topic
// or the trajectory file at fault.
TrajectorySettling SettleTrajectory(const std::filesystem::path& bag,
                                    const std::filesystem::path& trajectory,
                                    const TrajectorySettlingOptions& options,
                                    const ProgressCallback& progress = {},
                                    const WarningCallback& warn = {});

// As a JSON object (2-space indent): scans, scans_posed, scans_placed, scans_aligned,
// scan_pairs, point_pairs, usable and the move's ate_rmse_m, ate_max_m, rpe_trans_mean_m,
// rpe_rot_mean_deg.
std::string ToJson(const TrajectorySettling& settling);
// The scans aligned, the pairs matched and the move, as text.
std::string ToText(const TrajectorySettling& settling, const TrajectorySettlingOptions& options);

}  // namespace littermap::reconstruct
