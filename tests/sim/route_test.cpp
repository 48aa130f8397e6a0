// The robot's motion: it follows the waypoints, tilts on the bumps, and its odometry drifts as
// configured.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/odometry_model.hpp"
#include "sim/route.hpp"
#include "sim/simulation.hpp"
#include "sim_test_support.hpp"
#include "support/angles.hpp"

namespace littermap::sim {
namespace {

using test::SampleWorld;

using test::kDeg;

TEST(Route, DriveReachesTheLastWaypointThroughAllOthers) {
  const std::vector<Eigen::Vector2d> route = {{0, 0}, {10, 0}, {10, 5}, {2, 5}};
  const DriveResult drive = DriveRoute(route, {});
  ASSERT_TRUE(drive.reached_goal);
  const PlanarPose& end = drive.states.back().pose;
  EXPECT_NEAR(end.x_m, 2, 0.15);
  EXPECT_NEAR(end.y_m, 5, 0.15);
  for (const Eigen::Vector2d& waypoint : route) {
    double closest = 1e9;
    for (const RobotState& s : drive.states) {
      closest = std::min(closest, (Eigen::Vector2d(s.pose.x_m, s.pose.y_m) - waypoint).norm());
    }
    EXPECT_LT(closest, 0.2) << waypoint.transpose();
  }
  // Distance ≈ the polyline length (23 m); speed within limits.
  EXPECT_NEAR(drive.distance_m, 23, 0.5);
  for (const RobotState& s : drive.states) EXPECT_LE(s.linear_mps, 0.6 + 1e-9);
}

TEST(Route, LawnmowerSweepsThePolygonInLanes) {
  RouteSpec spec;
  spec.type = "lawnmower";
  spec.polygon_m = {{0, 0}, {20, 0}, {20, 10}, {0, 10}};
  spec.lane_spacing_m = 4;
  const auto route = PlanRoute(spec);
  ASSERT_EQ(route.size(), 4u);  // lanes at y = 2 and 6; y = 10 is the polygon's edge
  EXPECT_EQ(route[0], Eigen::Vector2d(0.5, 2));
  EXPECT_EQ(route[1], Eigen::Vector2d(19.5, 2));
  EXPECT_EQ(route[2], Eigen::Vector2d(19.5, 6));
  EXPECT_EQ(route[3], Eigen::Vector2d(0.5, 6));
}

TEST(Route, ComeHomeEndsTheSurveyWhereItBegan) {
  RouteSpec lanes;
  lanes.type = "lawnmower";
  lanes.polygon_m = {{0, 0}, {20, 0}, {20, 10}, {0, 10}};
  lanes.lane_spacing_m = 4;
  lanes.come_home = true;
  const auto route = PlanRoute(lanes);
  ASSERT_EQ(route.size(), 5u);  // the two lanes, then back to where the first began
  EXPECT_EQ(route[3], Eigen::Vector2d(0.5, 6));
  EXPECT_EQ(route[4], Eigen::Vector2d(0.5, 2));

  RouteSpec waypoints;
  waypoints.waypoints_m = {{0, 0}, {10, 0}, {10, 5}};
  waypoints.come_home = true;
  EXPECT_EQ(PlanRoute(waypoints).back(), Eigen::Vector2d(0, 0));
  EXPECT_EQ(PlanRoute(waypoints).size(), 4u);
  // A route that already ends at the dock gets no leg of zero length.
  waypoints.waypoints_m.push_back({0, 0});
  EXPECT_EQ(PlanRoute(waypoints).size(), 4u);
  // Driven, the survey stops at the dock; docking, the robot then turns in place to face the way
  // it left (east), so it ends where and as it began.
  DriveOptions docking;
  docking.dock = true;
  for (const bool dock : {false, true}) {
    docking.dock = dock;
    const DriveResult drive = DriveRoute(PlanRoute(lanes), docking);
    ASSERT_TRUE(drive.reached_goal);
    const PlanarPose& end = drive.states.back().pose;
    EXPECT_NEAR(end.x_m, 0.5, 0.15);
    EXPECT_NEAR(end.y_m, 2, 0.15);
    // It arrives heading south (down the polygon's edge from the last lane).
    EXPECT_NEAR(std::abs(end.theta_rad), dock ? 0 : std::numbers::pi / 2, dock ? 0.02 : 0.2);
  }
}

TEST(Route, BumpsTiltTheRobotAtTheConfiguredPlaces) {
  const WorldSpec spec = LoadWorldSpec(SampleWorld());
  const Simulation simulation(spec);
  ASSERT_EQ(spec.bumps.size(), 2u);
  for (const BumpSpec& bump : spec.bumps) {
    double peak_roll = 0, peak_pitch = 0, t_peak = -1;
    for (const RobotState& s : simulation.states()) {
      RollPitchYaw rpy;
      BasePose3(s.pose, simulation.world().terrain, spec.bumps, &rpy);
      if (std::abs(rpy.roll_rad) + std::abs(rpy.pitch_rad) >
          std::abs(peak_roll) + std::abs(peak_pitch)) {
        if ((Eigen::Vector2d(s.pose.x_m, s.pose.y_m) - Eigen::Vector2d(bump.x_m, bump.y_m)).norm() <
            bump.radius_m) {
          peak_roll = rpy.roll_rad;
          peak_pitch = rpy.pitch_rad;
          t_peak = s.t_s;
        }
      }
    }
    ASSERT_GE(t_peak, 0) << "the route misses the bump at " << bump.x_m << ", " << bump.y_m;
    EXPECT_GE(std::max(std::abs(peak_roll), std::abs(peak_pitch)), 10 * kDeg);
    // The terrain adds at most a few degrees to the bump's own tilt.
    EXPECT_NEAR(peak_roll, bump.roll_deg * kDeg, 3 * kDeg);
    EXPECT_NEAR(peak_pitch, bump.pitch_deg * kDeg, 3 * kDeg);
  }
  // Elsewhere the gentle terrain keeps the robot within a few degrees.
  RollPitchYaw level;
  BasePose3(simulation.states()[100].pose, simulation.world().terrain, spec.bumps, &level);
  EXPECT_LT(std::abs(level.roll_rad) + std::abs(level.pitch_rad), 8 * kDeg);
}

TEST(Route, SampleRouteTakesAboutThreeMinutes) {
  const Simulation simulation(LoadWorldSpec(SampleWorld()));
  EXPECT_TRUE(simulation.drive().reached_goal);
  EXPECT_GT(simulation.duration_s(), 150);
  EXPECT_LT(simulation.duration_s(), 210);
}

TEST(OdometryModel, DriftStatisticsFollowTheConfiguration) {
  // 200 runs of 50 m straight ahead in 1 cm steps.
  std::vector<PlanarPose> truth;
  for (int i = 0; i <= 5000; ++i) truth.push_back({0.01 * i, 0, 0});
  OdometrySpec spec;
  spec.scale_error = 0.02;
  spec.yaw_drift_deg_per_m = 0.2;
  spec.rotation_noise_deg_per_sqrt_m = 0.3;
  spec.translation_noise_m_per_sqrt_m = 0.01;
  double sum = 0, sum2 = 0;
  const int runs = 200;
  for (int run = 0; run < runs; ++run) {
    const auto odometry = SimulateOdometry(truth, spec, static_cast<std::uint64_t>(run));
    const double heading_error = odometry.back().theta_rad / kDeg;
    sum += heading_error;
    sum2 += heading_error * heading_error;
    if (run == 0) {
      // Distance travelled: 50 m × (1 + scale_error), ± noise and the bend of the heading drift.
      double travelled = 0;
      for (std::size_t i = 1; i < odometry.size(); ++i) {
        travelled += std::hypot(odometry[i].x_m - odometry[i - 1].x_m,
                                odometry[i].y_m - odometry[i - 1].y_m);
      }
      EXPECT_NEAR(travelled, 51, 0.3);
    }
  }
  const double mean = sum / runs, sigma = std::sqrt(sum2 / runs - mean * mean);
  // Mean 0.2°/m × 50 m = 10°; σ = 0.3 × √50 = 2.12°. 200 runs: mean ± 0.45° (3 SE), σ ± 15 %.
  EXPECT_NEAR(mean, 10, 0.45);
  EXPECT_NEAR(sigma, 0.3 * std::sqrt(50.0), 0.32);
}

TEST(OdometryModel, BumpSlipTurnsTheHeadingByItsAngleAcrossTheBump) {
  std::vector<PlanarPose> truth;
  for (int i = 0; i <= 1000; ++i) truth.push_back({0.01 * i, 0, 0});  // 10 m straight
  OdometrySpec exact;
  exact.scale_error = exact.yaw_drift_deg_per_m = 0;
  exact.translation_noise_m_per_sqrt_m = exact.rotation_noise_deg_per_sqrt_m = 0;
  BumpSpec bump;
  bump.x_m = 5;
  bump.radius_m = 0.4;
  bump.slip_deg = 7;
  const auto odometry = SimulateOdometry(truth, exact, 1, {bump});
  // Before the bump exact; after it turned by 7° (± one 1 cm step of 0.8 m).
  EXPECT_NEAR(odometry[400].theta_rad, 0, 1e-12);
  EXPECT_NEAR(odometry.back().theta_rad / kDeg, 7, 7 * 0.01 / 0.8 + 1e-9);
  // Off the bump's radius nothing slips.
  bump.y_m = 0.5;
  EXPECT_NEAR(SimulateOdometry(truth, exact, 1, {bump}).back().theta_rad, 0, 1e-12);
}

}  // namespace
}  // namespace littermap::sim
