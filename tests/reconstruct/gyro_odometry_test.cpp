// Wheel odometry turned by a gyro: the heading follows the gyro where the wheels drift, the
// wheels' own turn stands in across a gyro gap, and the pitch lifts the path up a slope but not
// over a bump.

#include "reconstruct/gyro_odometry.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

constexpr TimestampNs kStepNs = 20'000'000;  // 50 Hz
constexpr double kStepS = 0.02;

// A robot driving 0.5 m/s along a circle of radius 5 m (0.1 rad/s); its wheels believe the turn
// is 20 % faster. Odometry, gyro and pitch tick together.
struct Drive {
  GyroOdometry fused;
  PlanarPose wheels;
  PlanarPose truth;
  GyroOdometryPose last;

  void Step(int k, bool gyro = true, double pitch_rad = std::numeric_limits<double>::quiet_NaN()) {
    const TimestampNs stamp_ns = kStepNs * k;
    const double turn_rad = k > 0 ? 0.1 * kStepS : 0;  // the first reading is the start
    truth = Compose(truth, {k > 0 ? 0.5 * kStepS : 0, 0, turn_rad});
    wheels = Compose(wheels, {k > 0 ? 0.5 * kStepS : 0, 0, 1.2 * turn_rad});
    if (gyro) fused.AddYawRate(stamp_ns, 0.1);
    fused.AddPitch(pitch_rad);
    last = fused.AddOdometry(stamp_ns, wheels);
  }
};

TEST(GyroOdometry, HeadingFollowsTheGyroNotTheDriftingWheels) {
  Drive drive;
  for (int k = 0; k <= 500; ++k) drive.Step(k);  // 10 s, 5 m, 1 rad
  EXPECT_TRUE(drive.last.heading_from_gyro);
  EXPECT_NEAR(drive.last.T_odom_base.theta_rad, drive.truth.theta_rad, 1e-6);
  EXPECT_NEAR(drive.last.T_odom_base.x_m, drive.truth.x_m, 1e-3);
  EXPECT_NEAR(drive.last.T_odom_base.y_m, drive.truth.y_m, 1e-3);
  EXPECT_GT(std::abs(drive.wheels.theta_rad - drive.truth.theta_rad), 0.19);  // 0.2 rad off
  EXPECT_DOUBLE_EQ(drive.last.z_m, 0);                                        // no pitch known
}

TEST(GyroOdometry, WheelsTurnAcrossAGyroGapAndTheGyroTakesOverAfterIt) {
  Drive drive;
  for (int k = 0; k <= 100; ++k) drive.Step(k);
  // One second without gyro: the last rate holds for max_gyro_gap_s (0.1 s, readings of the two
  // sensors interleave), then the wheels turn, 20 % too far.
  for (int k = 101; k <= 150; ++k) {
    drive.Step(k, false);
    EXPECT_EQ(drive.last.heading_from_gyro, k <= 105) << k;
  }
  for (int k = 151; k <= 300; ++k) drive.Step(k);
  EXPECT_TRUE(drive.last.heading_from_gyro);
  // The wheels' extra turn over the gap stays, nothing more: 46 steps (106 to 151, the first
  // step back needs a gyro reading at both ends) turned 20 % too far.
  const double gap_error_rad = 46 * 0.2 * 0.1 * kStepS;
  EXPECT_NEAR(drive.last.T_odom_base.theta_rad - drive.truth.theta_rad, gap_error_rad, 1e-6);
}

TEST(GyroOdometry, ClimbsASlopeButNotOverABump) {
  Drive drive;
  const double slope_rad = -0.05;  // nose up: climbing
  for (int k = 0; k <= 500; ++k) {
    // A bump under one wheel for 0.5 m (1 s): the robot pitches 12 degrees without rising.
    const bool bump = k >= 200 && k < 250;
    drive.Step(k, true, slope_rad + (bump ? 0.2 : 0));
  }
  // 5 m driven at 0.05 rad: 0.25 m up; the bump's start, before it leaves the slope's median,
  // adds at most a centimetre.
  EXPECT_NEAR(drive.last.z_m, 5 * std::sin(0.05), 0.01);
}

TEST(GyroOdometry, IgnoresReadingsOutOfOrderAndRejectsBadOptions) {
  GyroOdometry fused;
  fused.AddYawRate(kStepNs, 0.1);
  const GyroOdometryPose first = fused.AddOdometry(kStepNs, {1, 2, 0.5});
  EXPECT_DOUBLE_EQ(first.T_odom_base.x_m, 1);                     // starts where the wheels are
  const GyroOdometryPose back = fused.AddOdometry(0, {5, 5, 0});  // passed on, as read
  EXPECT_FALSE(back.heading_from_gyro);
  EXPECT_DOUBLE_EQ(back.T_odom_base.x_m, 5);
  EXPECT_DOUBLE_EQ(back.T_odom_base.theta_rad, 0);
  fused.AddYawRate(0, 100);                     // out of order: ignored
  fused.AddYawRate(2 * kStepNs, std::nan(""));  // not a number: ignored
  fused.AddYawRate(2 * kStepNs, 0.1);
  const GyroOdometryPose next = fused.AddOdometry(2 * kStepNs, {1.01, 2, 0.7});
  EXPECT_TRUE(next.heading_from_gyro);
  EXPECT_NEAR(next.T_odom_base.theta_rad, 0.5 + 0.1 * kStepS, 1e-9);

  // Without a gyro the wheels' poses pass exactly as read (logs without an IMU are unchanged).
  GyroOdometry wheels_only;
  for (int k = 0; k < 100; ++k) {
    const PlanarPose wheels{0.013 * k, std::sin(0.1 * k), std::remainder(0.37 * k, 6.28)};
    const GyroOdometryPose pose = wheels_only.AddOdometry(kStepNs * k, wheels);
    EXPECT_EQ(pose.T_odom_base.x_m, wheels.x_m);
    EXPECT_EQ(pose.T_odom_base.y_m, wheels.y_m);
    EXPECT_EQ(pose.T_odom_base.theta_rad, wheels.theta_rad);
    EXPECT_FALSE(pose.heading_from_gyro);
  }

  GyroOdometryOptions bad;
  bad.max_gyro_gap_s = 0;
  EXPECT_THROW(GyroOdometry{bad}, UsageError);
  bad = {};
  bad.slope_window_m = -1;
  EXPECT_THROW(GyroOdometry{bad}, UsageError);
}

}  // namespace
}  // namespace littermap::reconstruct
