#pragma once
// Trajectory metrics with the definitions of the TUM RGB-D benchmark scripts (Sturm et al., IROS
// 2012: associate.py, evaluate_ate.py, evaluate_rpe.py), so numbers agree with them and with evo:
// - association: pairs whose stamps differ by less than max_time_difference_s, taken greedily in
//   order of increasing difference, each stamp used once (associate.py);
// - ATE: RMSE of position differences after the rigid (rotation + translation, no scale) Horn
//   alignment of the estimate onto the reference (evaluate_ate.py);
// - RPE: for every associated pose i, the pose j whose distance travelled along the estimate is
//   closest to delta_m further (evaluate_rpe.py --fixed_delta --delta_unit m; Kuemmerle et al.
//   2009 with 1 m pairs); error = (inv(E_i) E_j) * inv(inv(R_i) R_j), its translation norm and
//   rotation angle, exactly as evaluate_rpe.py composes it. Pairs are chosen by distance along the
//   estimate, as evaluate_rpe.py and evo (by default) do, not along the reference.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/planar_pose.hpp"
#include "core/stamped_pose.hpp"
#include "core/time.hpp"

namespace littermap::eval {

struct TrajectoryMetricsOptions {
  double max_time_difference_s = 0.02;  // associate.py's default
  double rpe_delta_m = 1.0;             // distance travelled between the poses of an RPE pair
  void Validate() const;
};

struct TrajectoryMetrics {
  std::size_t associated_poses = 0;
  double ate_rmse_m = 0;
  double ate_mean_m = 0;
  double ate_max_m = 0;
  std::size_t rpe_pairs = 0;
  double rpe_trans_mean_m = 0;
  double rpe_trans_rmse_m = 0;
  double rpe_rot_mean_deg = 0;
  Eigen::Isometry3d T_reference_estimate = Eigen::Isometry3d::Identity();  // the ATE alignment
};

// Index pairs (estimate, reference) as associate.py would produce them, sorted by estimate stamp.
std::vector<std::pair<std::size_t, std::size_t>> AssociateByTime(
    const std::vector<StampedPose>& estimate, const std::vector<StampedPose>& reference,
    double max_time_difference_s);

// The trajectory's pose nearest in time to each stamp, as a planar pose (the yaw of its
// orientation), if one is at most max_time_difference_s away. The trajectory need not be sorted.
// Throws UsageError for a negative or NaN max_time_difference_s.
std::vector<std::optional<PlanarPose>> PlanarPosesAt(const std::vector<StampedPose>& trajectory,
                                                     const std::vector<TimestampNs>& stamps_ns,
                                                     double max_time_difference_s);

// Throws BadInputError if fewer than 2 poses associate (or fewer than 3 for the alignment).
TrajectoryMetrics EvaluateTrajectory(const std::vector<StampedPose>& estimate,
                                     const std::vector<StampedPose>& reference,
                                     const TrajectoryMetricsOptions& options);
// The same for two TUM trajectory files. Throws BadInputError naming a file that cannot be read.
TrajectoryMetrics EvaluateTrajectory(const std::filesystem::path& estimate,
                                     const std::filesystem::path& reference,
                                     const TrajectoryMetricsOptions& options);

// The metrics as a JSON object (2-space indent): ate_rmse_m, ate_mean_m, ate_max_m,
// rpe_trans_mean_m, rpe_trans_rmse_m, rpe_rot_mean_deg, associated_poses, rpe_pairs.
std::string ToJson(const TrajectoryMetrics& metrics);

// The metrics as text lines: associated poses, ATE (RMSE, mean, max), RPE (translation mean and
// RMSE over the pairs options.rpe_delta_m apart, rotation mean).
std::string ToText(const TrajectoryMetrics& metrics, const TrajectoryMetricsOptions& options);

}  // namespace littermap::eval
