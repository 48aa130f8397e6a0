// Scan to points: with the base's tilt known, echoes where a tilted beam meets the ground are
// dropped (the ground arc a bump shows the scanner moves with the robot and would hold ICP).

#include "reconstruct/scan_points.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace littermap::reconstruct {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// 360 beams all round, every one with an echo at 5 m.
LaserScan RingScan() {
  LaserScan scan;
  scan.angle_min_rad = -std::numbers::pi;
  scan.angle_increment_rad = 2 * std::numbers::pi / 360;
  scan.range_min_m = 0.05;
  scan.range_max_m = 30;
  scan.ranges_m.assign(360, 5.0f);
  return scan;
}

TEST(ScanPoints, TiltedScannerDropsItsGroundHits) {
  ScanPointsOptions options;
  options.laser_height_m = 0.3;
  // Nose down 5 degrees: a beam at heading a meets the ground at 0.3 / (sin 5deg cos a) m; with
  // the 0.8 margin an echo at 5 m counts as ground where cos a >= 0.24 / (5 sin 5deg) = 0.551,
  // |a| <= 56.6 degrees: 113 of the 360 beams.
  const ScanPoints tilted = ScanToPoints(RingScan(), {}, options, Tilt{0, 5 * kDeg});
  EXPECT_NEAR(static_cast<double>(tilted.ground_beams), 113, 2);
  EXPECT_EQ(tilted.points_base.size() + tilted.ground_beams, 360u);
  for (const Eigen::Vector2d& p : tilted.points_base) EXPECT_LT(p.x() / p.norm(), 0.56);
  // Rolled left side up 5 degrees: the right side (negative y) looks at the ground instead.
  const ScanPoints rolled = ScanToPoints(RingScan(), {}, options, Tilt{5 * kDeg, 0});
  EXPECT_NEAR(static_cast<double>(rolled.ground_beams), 113, 2);
  for (const Eigen::Vector2d& p : rolled.points_base) EXPECT_GT(p.y() / p.norm(), -0.56);
  // Level, no tilt known, or no height known: nothing is dropped.
  EXPECT_EQ(ScanToPoints(RingScan(), {}, options, Tilt{}).points_base.size(), 360u);
  EXPECT_EQ(ScanToPoints(RingScan(), {}, options).points_base.size(), 360u);
  EXPECT_EQ(ScanToPoints(RingScan(), {}, {}, Tilt{0, 5 * kDeg}).points_base.size(), 360u);
}

}  // namespace
}  // namespace littermap::reconstruct
