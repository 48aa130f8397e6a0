// Scan to points: with the base's tilt known, echoes where a tilted beam meets the ground are
// dropped (the ground arc a bump shows the scanner moves with the robot and would hold ICP).

#include "reconstruct/scan_points.hpp"
#include "support/angles.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

namespace littermap::reconstruct {
namespace {

using test::kDeg;

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

TEST(ScanPoints, TiltedEchoesLieWhereTheBeamMetTheUprightObstacle) {
  // Each echo lies at the ground-plane position of the 3D point the tilted beam reached: the
  // beam's direction rotated by R = Ry(pitch) Rx(roll), taken in x and y, times the range.
  const PlanarPose T_base_laser{0.2, -0.1, 0.3};
  const Tilt tilt{-6 * kDeg, 14 * kDeg};
  const ScanPoints points = ScanToPoints(RingScan(), T_base_laser, {}, tilt);
  ASSERT_EQ(points.points_base.size(), 360u);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(tilt.pitch_rad, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(tilt.roll_rad, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const LaserScan scan = RingScan();
  for (std::size_t i = 0; i < 360; i += 7) {
    const double heading = scan.AngleOf(i) + T_base_laser.theta_rad;
    const Eigen::Vector3d beam = R * Eigen::Vector3d(std::cos(heading), std::sin(heading), 0);
    const Eigen::Vector2d expected =
        Eigen::Vector2d(T_base_laser.x_m, T_base_laser.y_m) + 5.0 * beam.head<2>();
    EXPECT_NEAR((points.points_base[i] - expected).norm(), 0, 1e-9) << i;
  }
  // Straight ahead on a 14-degree root, a trunk 5 m along the beam is 4.851 m away on the ground:
  // 15 cm nearer than a flat scan puts it.
  const ScanPoints pitched = ScanToPoints(RingScan(), {}, {}, Tilt{0, 14 * kDeg});
  EXPECT_NEAR(pitched.points_base[180].x(), 5 * std::cos(14 * kDeg), 1e-9);
  EXPECT_NEAR(pitched.points_base[180].x(), 4.851, 1e-3);
  // Level, a flat scan is what it was.
  const ScanPoints level = ScanToPoints(RingScan(), T_base_laser, {}, Tilt{});
  const ScanPoints flat = ScanToPoints(RingScan(), T_base_laser, {});
  for (std::size_t i = 0; i < 360; ++i) {
    EXPECT_NEAR((level.points_base[i] - flat.points_base[i]).norm(), 0, 1e-12);
  }
}

}  // namespace
}  // namespace littermap::reconstruct
