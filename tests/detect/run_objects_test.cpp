#include "detect/run_objects.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace littermap::detect {
namespace {

StampedPose Pose(TimestampNs t, double x, double y, double yaw) {
  StampedPose p;
  p.stamp_ns = t;
  p.position_m = {x, y, 0};
  p.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return p;
}

TEST(InterpolatePose, InterpolatesPositionAndYawAcrossTheBranchCut) {
  const std::vector<StampedPose> trajectory = {Pose(0, 0, 0, 3.0), Pose(1'000'000'000, 1, 2, -3.0)};
  const auto T = InterpolatePose(trajectory, 250'000'000, 2.0);
  ASSERT_TRUE(T.has_value());
  EXPECT_NEAR(T->translation().x(), 0.25, 1e-9);
  EXPECT_NEAR(T->translation().y(), 0.5, 1e-9);
  // From 3.0 to -3.0 the short way is through pi: a quarter of 2pi - 6 past 3.0.
  const Eigen::Vector3d x_axis = T->linear().col(0);
  EXPECT_NEAR(std::remainder(std::atan2(x_axis.y(), x_axis.x()) - (3.0 + 0.25 * (2 * M_PI - 6.0)),
                             2 * M_PI),
              0.0, 1e-9);
}

TEST(InterpolatePose, RefusesOutsideTheTrajectoryAndAcrossGaps) {
  const std::vector<StampedPose> trajectory = {Pose(1'000, 0, 0, 0), Pose(2'000, 1, 0, 0),
                                               Pose(5'000'000'000, 2, 0, 0)};
  EXPECT_FALSE(InterpolatePose(trajectory, 999, 0.5).has_value());
  EXPECT_TRUE(InterpolatePose(trajectory, 1'000, 0.5).has_value());
  EXPECT_FALSE(InterpolatePose(trajectory, 3'000'000'000, 0.5).has_value());
  EXPECT_FALSE(InterpolatePose(trajectory, 6'000'000'000, 0.5).has_value());
}

}  // namespace
}  // namespace littermap::detect
