#include "eval/trajectory_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>

#include <Eigen/Geometry>

#include <nlohmann/json.hpp>

#include "bag/tum_trajectory.hpp"
#include "core/error.hpp"
#include "core/pose3.hpp"
#include "eval/text_format.hpp"

namespace littermap::eval {
namespace {

Eigen::Isometry3d ToIsometry(const StampedPose& pose) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = pose.orientation.normalized().toRotationMatrix();
  T.translation() = pose.position_m;
  return T;
}

// Angle of a rotation matrix, as evaluate_rpe.py's compute_angle (clamped acos of the trace).
double RotationAngleRad(const Eigen::Matrix3d& R) {
  return std::acos(std::clamp((R.trace() - 1.0) / 2.0, -1.0, 1.0));
}

// evaluate_rpe.py's find_closest_index on a sorted list.
std::size_t ClosestIndex(const std::vector<double>& sorted, double value) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), value);
  if (it == sorted.begin()) return 0;
  if (it == sorted.end()) return sorted.size() - 1;
  const auto index = static_cast<std::size_t>(it - sorted.begin());
  return (value - sorted[index - 1] <= sorted[index] - value) ? index - 1 : index;
}

// The pose of a trajectory sorted by stamp nearest in time to stamp_ns, if close enough.
std::optional<PlanarPose> PlanarPoseNearest(const std::vector<StampedPose>& sorted,
                                            TimestampNs stamp_ns, double max_time_difference_s) {
  const auto after = std::lower_bound(
      sorted.begin(), sorted.end(), stamp_ns,
      [](const StampedPose& pose, TimestampNs value) { return pose.stamp_ns < value; });
  const StampedPose* best = nullptr;
  double best_s = std::numeric_limits<double>::infinity();
  for (auto it : {after, after == sorted.begin() ? sorted.end() : std::prev(after)}) {
    if (it == sorted.end()) continue;
    const double difference_s = std::abs(ToSeconds(it->stamp_ns - stamp_ns));
    if (difference_s < best_s) {
      best_s = difference_s;
      best = &*it;
    }
  }
  if (best == nullptr || best_s > max_time_difference_s) return std::nullopt;
  return PlanarPoseOf(*best);
}

}  // namespace

void TrajectoryMetricsOptions::Validate() const {
  if (!(max_time_difference_s > 0)) {
    throw UsageError("max_time_difference_s must be > 0, got " +
                     std::to_string(max_time_difference_s));
  }
  if (!(rpe_delta_m > 0)) {
    throw UsageError("rpe_delta_m must be > 0, got " + std::to_string(rpe_delta_m));
  }
}

std::vector<std::pair<std::size_t, std::size_t>> AssociateByTime(
    const std::vector<StampedPose>& estimate, const std::vector<StampedPose>& reference,
    double max_time_difference_s) {
  // Candidates with |a - b| < max difference (strict, as associate.py), found by binary search
  // on the reference stamps sorted by time.
  std::vector<std::size_t> reference_order(reference.size());
  for (std::size_t i = 0; i < reference.size(); ++i) reference_order[i] = i;
  std::stable_sort(
      reference_order.begin(), reference_order.end(),
      [&](std::size_t a, std::size_t b) { return reference[a].stamp_ns < reference[b].stamp_ns; });
  const auto max_ns = static_cast<double>(max_time_difference_s * 1e9);
  std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
  for (std::size_t e = 0; e < estimate.size(); ++e) {
    const TimestampNs low = estimate[e].stamp_ns - static_cast<TimestampNs>(std::ceil(max_ns));
    auto it = std::lower_bound(
        reference_order.begin(), reference_order.end(), low,
        [&](std::size_t r, TimestampNs value) { return reference[r].stamp_ns < value; });
    for (; it != reference_order.end(); ++it) {
      const double difference =
          std::abs(static_cast<double>(reference[*it].stamp_ns - estimate[e].stamp_ns));
      if (reference[*it].stamp_ns > estimate[e].stamp_ns && difference >= max_ns) break;
      if (difference < max_ns) candidates.emplace_back(difference, e, *it);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> estimate_used(estimate.size(), false);
  std::vector<bool> reference_used(reference.size(), false);
  std::vector<std::pair<std::size_t, std::size_t>> matches;
  for (const auto& [difference, e, r] : candidates) {
    if (estimate_used[e] || reference_used[r]) continue;
    estimate_used[e] = reference_used[r] = true;
    matches.emplace_back(e, r);
  }
  std::sort(matches.begin(), matches.end(), [&](const auto& a, const auto& b) {
    return estimate[a.first].stamp_ns < estimate[b.first].stamp_ns;
  });
  return matches;
}

TrajectoryMetrics EvaluateTrajectory(const std::vector<StampedPose>& estimate,
                                     const std::vector<StampedPose>& reference,
                                     const TrajectoryMetricsOptions& options) {
  options.Validate();
  const auto matches = AssociateByTime(estimate, reference, options.max_time_difference_s);
  if (matches.size() < 3) {
    throw BadInputError("only " + std::to_string(matches.size()) + " poses associate within " +
                        std::to_string(options.max_time_difference_s) +
                        " s; the trajectories do not cover the same time");
  }
  TrajectoryMetrics metrics;
  metrics.associated_poses = matches.size();
  const auto n = static_cast<Eigen::Index>(matches.size());
  Eigen::Matrix3Xd est(3, n), ref(3, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    est.col(k) = estimate[matches[static_cast<std::size_t>(k)].first].position_m;
    ref.col(k) = reference[matches[static_cast<std::size_t>(k)].second].position_m;
  }
  // Horn's closed form = Umeyama without scale (evaluate_ate.py's align()).
  const Eigen::Matrix4d T = Eigen::umeyama(est, ref, false);
  metrics.T_reference_estimate.matrix() = T;
  double sum_squared = 0, sum = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double error =
        (metrics.T_reference_estimate * Eigen::Vector3d(est.col(k)) - Eigen::Vector3d(ref.col(k)))
            .norm();
    sum_squared += error * error;
    sum += error;
    metrics.ate_max_m = std::max(metrics.ate_max_m, error);
  }
  metrics.ate_rmse_m = std::sqrt(sum_squared / static_cast<double>(n));
  metrics.ate_mean_m = sum / static_cast<double>(n);

  // RPE over pairs a fixed distance apart along the estimate (evaluate_rpe.py, --delta_unit m).
  std::vector<double> travelled(matches.size(), 0.0);
  for (std::size_t k = 1; k < matches.size(); ++k) {
    travelled[k] =
        travelled[k - 1] +
        (estimate[matches[k].first].position_m - estimate[matches[k - 1].first].position_m).norm();
  }
  double trans_sum = 0, trans_squared = 0, rot_sum = 0;
  for (std::size_t i = 0; i < matches.size(); ++i) {
    const std::size_t j = ClosestIndex(travelled, travelled[i] + options.rpe_delta_m);
    if (j == matches.size() - 1) continue;  // as evaluate_rpe.py: the end is not a pair
    const Eigen::Isometry3d est_ij =
        ToIsometry(estimate[matches[i].first]).inverse() * ToIsometry(estimate[matches[j].first]);
    const Eigen::Isometry3d ref_ij = ToIsometry(reference[matches[i].second]).inverse() *
                                     ToIsometry(reference[matches[j].second]);
    // evaluate_rpe.py: ominus(ominus(E_j, E_i), ominus(G_j, G_i)) with ominus(a, b) = a^-1 b,
    // i.e. est_ij * ref_ij^-1: a rotation error over the pair also moves the translation.
    const Eigen::Isometry3d error = est_ij * ref_ij.inverse();
    const double trans = error.translation().norm();
    trans_sum += trans;
    trans_squared += trans * trans;
    rot_sum += RotationAngleRad(error.linear());
    ++metrics.rpe_pairs;
  }
  if (metrics.rpe_pairs > 0) {
    const auto pairs = static_cast<double>(metrics.rpe_pairs);
    metrics.rpe_trans_mean_m = trans_sum / pairs;
    metrics.rpe_trans_rmse_m = std::sqrt(trans_squared / pairs);
    metrics.rpe_rot_mean_deg = rot_sum / pairs * 180.0 / std::numbers::pi;
  }
  return metrics;
}

std::vector<std::optional<PlanarPose>> PlanarPosesAt(const std::vector<StampedPose>& trajectory,
                                                     const std::vector<TimestampNs>& stamps_ns,
                                                     double max_time_difference_s) {
  if (!(max_time_difference_s >= 0)) {
    throw UsageError("max_time_difference_s must be >= 0");
  }
  std::vector<StampedPose> sorted = trajectory;
  std::stable_sort(sorted.begin(), sorted.end(), [](const StampedPose& a, const StampedPose& b) {
    return a.stamp_ns < b.stamp_ns;
  });
  std::vector<std::optional<PlanarPose>> poses;
  poses.reserve(stamps_ns.size());
  for (TimestampNs stamp_ns : stamps_ns) {
    poses.push_back(PlanarPoseNearest(sorted, stamp_ns, max_time_difference_s));
  }
  return poses;
}

TrajectoryMetrics EvaluateTrajectory(const std::filesystem::path& estimate,
                                     const std::filesystem::path& reference,
                                     const TrajectoryMetricsOptions& options) {
  return EvaluateTrajectory(bag::ReadTumTrajectory(estimate), bag::ReadTumTrajectory(reference),
                            options);
}

std::string ToJson(const TrajectoryMetrics& metrics) {
  nlohmann::ordered_json json;
  json["ate_rmse_m"] = metrics.ate_rmse_m;
  json["ate_mean_m"] = metrics.ate_mean_m;
  json["ate_max_m"] = metrics.ate_max_m;
  json["rpe_trans_mean_m"] = metrics.rpe_trans_mean_m;
  json["rpe_trans_rmse_m"] = metrics.rpe_trans_rmse_m;
  json["rpe_rot_mean_deg"] = metrics.rpe_rot_mean_deg;
  json["associated_poses"] = metrics.associated_poses;
  json["rpe_pairs"] = metrics.rpe_pairs;
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string ToText(const TrajectoryMetrics& metrics, const TrajectoryMetricsOptions& options) {
  std::string text;
  AppendFormat(text, "associated poses   %zu\n", metrics.associated_poses);
  AppendFormat(text, "ATE RMSE           %.4f m (mean %.4f m, max %.4f m)\n", metrics.ate_rmse_m,
               metrics.ate_mean_m, metrics.ate_max_m);
  AppendFormat(text, "RPE translation    %.4f m mean, %.4f m RMSE over %zu pairs %.2f m apart\n",
               metrics.rpe_trans_mean_m, metrics.rpe_trans_rmse_m, metrics.rpe_pairs,
               options.rpe_delta_m);
  AppendFormat(text, "RPE rotation       %.3f deg mean\n", metrics.rpe_rot_mean_deg);
  text.pop_back();  // the caller ends the last line, as after ToJson
  return text;
}

}  // namespace littermap::eval
