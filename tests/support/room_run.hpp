#pragma once
// Scans of a known room for the tests of trajectory measures: a square room, a laser on a base
// driving a circle in it, the true poses, and those poses with seeded noise.

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "eval/trajectory_metrics.hpp"
#include "support/angles.hpp"

namespace littermap::test {

// A square room [2 cm, 10.02 m]^2: its walls run through the middle of 5 cm cells, not along
// cell borders (where rounding would split a wall over two rows).
constexpr double kWallM = 0.02;
constexpr double kRoomM = 10;

// Range from (x, y) along world angle a to the room's walls.
inline double RangeToWalls(double x, double y, double a) {
  const double c = std::cos(a), s = std::sin(a);
  double range = std::numeric_limits<double>::infinity();
  if (c > 1e-12) range = std::min(range, (kWallM + kRoomM - x) / c);
  if (c < -1e-12) range = std::min(range, (kWallM - x) / c);
  if (s > 1e-12) range = std::min(range, (kWallM + kRoomM - y) / s);
  if (s < -1e-12) range = std::min(range, (kWallM - y) / s);
  return range;
}

// 360 beams over 360° from laser pose T_world_laser, stamped at stamp_ns.
inline LaserScan ScanFrom(const PlanarPose& T_world_laser, TimestampNs stamp_ns) {
  LaserScan scan;
  scan.stamp_ns = stamp_ns;
  scan.angle_min_rad = -std::numbers::pi;
  scan.angle_increment_rad = std::numbers::pi / 180;
  scan.range_min_m = 0.05;
  scan.range_max_m = 30;
  for (int i = 0; i < 360; ++i) {
    scan.ranges_m.push_back(static_cast<float>(RangeToWalls(
        T_world_laser.x_m, T_world_laser.y_m, T_world_laser.theta_rad + scan.AngleOf(i))));
  }
  return scan;
}

struct RoomScans {
  std::vector<LaserScan> scans;
  std::vector<StampedPose> truth;
};

inline const PlanarPose kBaseLaser{0.2, 0.05, 0.1};

// 100 scans along a loop inside the room, 0.1 s apart, the laser mounted off centre and turned.
inline RoomScans RoomRun() {
  RoomScans run;
  for (int k = 0; k < 100; ++k) {
    const double phase = 2 * std::numbers::pi * k / 100;
    const PlanarPose T_world_base{5 + 3 * std::cos(phase), 5 + 3 * std::sin(phase),
                                  phase + std::numbers::pi / 2};
    const TimestampNs stamp_ns = 1'000'000'000LL + k * 100'000'000LL;
    run.truth.push_back(StampedPoseFromPlanar(stamp_ns, T_world_base));
    run.scans.push_back(ScanFrom(Compose(T_world_base, kBaseLaser), stamp_ns));
  }
  return run;
}

inline std::vector<StampedPose> Perturbed(const std::vector<StampedPose>& poses, double sigma_m,
                                          double sigma_rad) {
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  std::vector<StampedPose> perturbed;
  for (const StampedPose& pose : poses) {
    const double yaw = std::atan2(pose.orientation.toRotationMatrix()(1, 0),
                                  pose.orientation.toRotationMatrix()(0, 0));
    perturbed.push_back(StampedPoseFromPlanar(
        pose.stamp_ns,
        {pose.position_m.x() + sigma_m * normal(random),
         pose.position_m.y() + sigma_m * normal(random), yaw + sigma_rad * normal(random)}));
  }
  return perturbed;
}

}  // namespace littermap::test
