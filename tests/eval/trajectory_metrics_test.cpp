// Trajectory metrics against cases with known answers, and the association rule of the TUM
// benchmark's associate.py (greedy by smallest time difference, strict max difference).

#include "eval/trajectory_metrics.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace littermap::eval {
namespace {

StampedPose Pose(double t_s, double x, double y, double yaw_rad, double z = 0) {
  StampedPose pose;
  pose.stamp_ns = static_cast<TimestampNs>(std::llround(t_s * 1e9));
  pose.position_m = {x, y, z};
  pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()));
  return pose;
}

// A 10 m x 6 m rectangle driven at 0.1 m per pose, heading along the path.
std::vector<StampedPose> Rectangle() {
  std::vector<StampedPose> poses;
  double x = 0, y = 0, t = 0;
  const double legs[4][3] = {{1, 0, 100}, {0, 1, 60}, {-1, 0, 100}, {0, -1, 60}};
  for (const auto& leg : legs) {
    for (int i = 0; i < static_cast<int>(leg[2]); ++i) {
      poses.push_back(Pose(t, x, y, std::atan2(leg[1], leg[0])));
      x += 0.1 * leg[0];
      y += 0.1 * leg[1];
      t += 0.1;
    }
  }
  return poses;
}

TEST(TrajectoryMetrics, RigidlyMovedCopyHasZeroError) {
  const auto reference = Rectangle();
  const Eigen::Isometry3d T =
      Eigen::Translation3d(5, -3, 0.5) * Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ());
  std::vector<StampedPose> estimate;
  for (StampedPose pose : reference) {
    pose.position_m = T * pose.position_m;
    pose.orientation = Eigen::Quaterniond(T.linear()) * pose.orientation;
    estimate.push_back(pose);
  }
  const TrajectoryMetrics metrics = EvaluateTrajectory(estimate, reference, {});
  EXPECT_EQ(metrics.associated_poses, reference.size());
  EXPECT_LT(metrics.ate_rmse_m, 1e-9);
  EXPECT_LT(metrics.rpe_trans_mean_m, 1e-9);
  EXPECT_LT(metrics.rpe_rot_mean_deg, 1e-6);
  EXPECT_GT(metrics.rpe_pairs, 250u);
}

TEST(TrajectoryMetrics, AlternatingHeightErrorGivesItsRmse) {
  // +-0.1 m off the plane, alternating: no rigid motion removes it, so ATE RMSE = 0.1 m.
  const auto reference = Rectangle();
  std::vector<StampedPose> estimate = reference;
  for (std::size_t i = 0; i < estimate.size(); ++i) estimate[i].position_m.z() = i % 2 ? 0.1 : -0.1;
  const TrajectoryMetrics metrics = EvaluateTrajectory(estimate, reference, {});
  EXPECT_NEAR(metrics.ate_rmse_m, 0.1, 1e-3);
  // RPE pairs are 1 m = 10 poses apart, an even gap: both ends on the same side, no error.
  EXPECT_LT(metrics.rpe_trans_mean_m, 1e-9);
}

TEST(TrajectoryMetrics, HeadingDriftGivesKnownRotationError) {
  // Straight line, 0.1 m per pose; the estimate's heading drifts 0.001 rad per pose, so every
  // pair 1 m (10 poses) apart is 0.01 rad off.
  std::vector<StampedPose> reference, estimate;
  for (int i = 0; i < 200; ++i) {
    reference.push_back(Pose(i * 0.1, i * 0.1, 0, 0));
    estimate.push_back(Pose(i * 0.1, i * 0.1, 0, 0.001 * i));
  }
  const TrajectoryMetrics metrics = EvaluateTrajectory(estimate, reference, {});
  EXPECT_NEAR(metrics.rpe_rot_mean_deg, 0.01 * 180 / std::numbers::pi, 1e-6);
  EXPECT_LT(metrics.ate_rmse_m, 1e-9);  // positions agree exactly
}

TEST(TrajectoryMetrics, RpeComposesTheErrorLikeEvaluateRpePy) {
  // Straight line, exact positions, heading drifting 0.001 rad per pose. For the pair (i, j = i +
  // 10) the estimate's relative motion is A = (R(0.01), R(-0.001 i) (1, 0)) and the reference's
  // B = (I, (1, 0)). evaluate_rpe.py's error A * inv(B) has translation t_A - R_A t_B, of length
  // 2 sin((0.01 + 0.001 i) / 2); inv(B) * A (the other order) would give 2 sin(0.0005 i).
  std::vector<StampedPose> reference, estimate;
  for (int i = 0; i < 200; ++i) {
    reference.push_back(Pose(i * 0.1, i * 0.1, 0, 0));
    estimate.push_back(Pose(i * 0.1, i * 0.1, 0, 0.001 * i));
  }
  const TrajectoryMetrics metrics = EvaluateTrajectory(estimate, reference, {});
  double expected = 0;
  std::size_t pairs = 0;
  for (int i = 0; i + 10 < 199; ++i, ++pairs) expected += 2 * std::sin((0.01 + 0.001 * i) / 2);
  ASSERT_EQ(metrics.rpe_pairs, pairs);
  EXPECT_NEAR(metrics.rpe_trans_mean_m, expected / static_cast<double>(pairs), 1e-6);
}

TEST(TrajectoryMetrics, AssociationIsGreedyByTimeDifferenceLikeAssociatePy) {
  // associate.py: candidates sorted by |a - b|, each stamp used once, |a - b| < max strictly.
  const std::vector<StampedPose> estimate = {Pose(0.000, 0, 0, 0), Pose(0.010, 0, 0, 0),
                                             Pose(1.000, 0, 0, 0), Pose(2.000, 0, 0, 0)};
  const std::vector<StampedPose> reference = {Pose(0.006, 0, 0, 0), Pose(1.019, 0, 0, 0),
                                              Pose(2.020, 0, 0, 0)};
  const auto matches = AssociateByTime(estimate, reference, 0.02);
  ASSERT_EQ(matches.size(), 2u);
  EXPECT_EQ(matches[0], (std::pair<std::size_t, std::size_t>(1, 0)));  // 0.004 beats 0.006
  EXPECT_EQ(matches[1], (std::pair<std::size_t, std::size_t>(2, 1)));  // 0.019 < 0.02
  // 2.000 vs 2.020 differ by exactly the maximum: not associated (strict, as associate.py).
}

TEST(TrajectoryMetrics, DisjointTrajectoriesAreBadInput) {
  const std::vector<StampedPose> estimate = {Pose(0, 0, 0, 0), Pose(1, 0, 0, 0), Pose(2, 0, 0, 0)};
  const std::vector<StampedPose> reference = {Pose(10, 0, 0, 0), Pose(11, 0, 0, 0),
                                              Pose(12, 0, 0, 0)};
  EXPECT_THROW(EvaluateTrajectory(estimate, reference, {}), BadInputError);
  TrajectoryMetricsOptions options;
  options.max_time_difference_s = 0;
  EXPECT_THROW(EvaluateTrajectory(estimate, estimate, options), UsageError);
}

}  // namespace
}  // namespace littermap::eval
