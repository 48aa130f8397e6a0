// Odometry history: a scan between two odometry readings gets the pose interpolated between
// them, not the older reading (up to 20 ms stale with wheels at 50 Hz and a laser at 40 Hz).

#include "reconstruct/odometry_history.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

GyroOdometryPose Reading(double x_m, double theta_rad, double z_m = 0, bool gyro = true) {
  return {{x_m, 0.5 * x_m, theta_rad}, gyro, z_m};
}

TEST(OdometryHistory, InterpolatesBetweenTheReadingsAroundAStamp) {
  OdometryHistory history(0.2);
  history.Add(FromSeconds(1.00), Reading(1.0, 0.1, 0.0));
  history.Add(FromSeconds(1.02), Reading(1.2, 0.3, 0.02));
  EXPECT_TRUE(history.Covers(FromSeconds(1.015)));
  EXPECT_FALSE(history.Covers(FromSeconds(1.025)));
  const auto pose = history.At(FromSeconds(1.015));
  ASSERT_TRUE(pose);
  EXPECT_NEAR(pose->T_odom_base.x_m, 1.15, 1e-9);
  EXPECT_NEAR(pose->T_odom_base.y_m, 0.575, 1e-9);
  EXPECT_NEAR(pose->T_odom_base.theta_rad, 0.25, 1e-9);
  EXPECT_NEAR(pose->z_m, 0.015, 1e-9);
  EXPECT_TRUE(pose->heading_from_gyro);
  // A reading at the very stamp is taken as it is.
  EXPECT_NEAR(history.At(FromSeconds(1.02))->T_odom_base.x_m, 1.2, 1e-12);
}

TEST(OdometryHistory, InterpolatesTheHeadingAcrossPlusMinusPi) {
  OdometryHistory history(0.2);
  history.Add(FromSeconds(0.0), Reading(0, std::numbers::pi - 0.1));
  history.Add(FromSeconds(0.1), Reading(0, -std::numbers::pi + 0.1));
  const double theta = history.At(FromSeconds(0.05))->T_odom_base.theta_rad;
  EXPECT_NEAR(std::abs(theta), std::numbers::pi, 1e-9);  // through pi, not through 0
}

TEST(OdometryHistory, OutsideTheReadingsTakesTheNearestWithinTheAgeLimit) {
  OdometryHistory history(0.2);
  EXPECT_FALSE(history.At(FromSeconds(1.0)));
  history.Add(FromSeconds(1.0), Reading(1.0, 0));
  history.Add(FromSeconds(1.1), Reading(2.0, 0));
  EXPECT_NEAR(history.At(FromSeconds(1.25))->T_odom_base.x_m, 2.0, 1e-12);
  EXPECT_NEAR(history.At(FromSeconds(0.9))->T_odom_base.x_m, 1.0, 1e-12);
  EXPECT_FALSE(history.At(FromSeconds(1.35)));  // odometry stopped: none rather than stale
  EXPECT_FALSE(history.At(FromSeconds(0.7)));
}

TEST(OdometryHistory, AGyroGapOnEitherSideIsNotAGyroHeading) {
  OdometryHistory history(0.2);
  history.Add(FromSeconds(0.00), Reading(0, 0, 0, true));
  history.Add(FromSeconds(0.02), Reading(0.1, 0, 0, false));
  EXPECT_FALSE(history.At(FromSeconds(0.01))->heading_from_gyro);
}

TEST(OdometryHistory, DropsWhatNoLaterStampNeedsAndIgnoresOlderReadings) {
  OdometryHistory history(0.2);
  for (int i = 0; i <= 10; ++i) history.Add(FromSeconds(0.02 * i), Reading(0.02 * i, 0));
  history.Add(FromSeconds(0.1), Reading(99, 0));  // out of order: ignored
  history.DropBefore(FromSeconds(0.13));
  EXPECT_NEAR(history.At(FromSeconds(0.13))->T_odom_base.x_m, 0.13, 1e-9);  // 0.12 kept
  EXPECT_NEAR(history.At(FromSeconds(0.10))->T_odom_base.x_m, 0.12, 1e-9);  // nearest left
}

TEST(OdometryHistory, RejectsANonPositiveAgeLimit) { EXPECT_THROW(OdometryHistory{0}, UsageError); }

}  // namespace
}  // namespace littermap::reconstruct
