// Laser ranges against analytic geometry. With σ = 0 the ray caster is exact up to float
// rounding of the published ranges (|r| < 30 m: < 2e-6 m), so 1e-4 m is a safe tolerance.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "sim/laser_simulator.hpp"
#include "sim_test_support.hpp"

namespace littermap::sim {
namespace {

using test::EmptyWorld;
using test::MakePrimitive;

constexpr double kExactM = 1e-4;
constexpr double kLaserHeightM = 0.3;

LaserSimulatorOptions Exact(const char* preset = "utm-30lx") {
  LaserSimulatorOptions options;
  options.model = LaserPreset(preset);
  options.range_noise_sigma_m = 0;
  options.mixed_pixel_probability = 0;
  options.dropout_probability = 0;
  return options;
}

Eigen::Isometry3d LevelLaser() { return MakeIsometry({0, 0, kLaserHeightM}, {}); }

// The beam nearest to `angle_rad`.
std::size_t BeamAt(const LaserScan& scan, double angle_rad) {
  return static_cast<std::size_t>(
      std::lround((angle_rad - scan.angle_min_rad) / scan.angle_increment_rad));
}

TEST(LaserSimulator, PresetsMatchDataSheets) {
  const LaserModel urg = LaserPreset("urg-04lx");
  EXPECT_EQ(urg.beams, 682);
  EXPECT_DOUBLE_EQ(urg.range_max_m, 5.6);
  EXPECT_NEAR(urg.fov_rad, 240 * std::numbers::pi / 180, 1e-12);
  const LaserModel utm = LaserPreset("utm-30lx");
  EXPECT_EQ(utm.beams, 1081);
  EXPECT_DOUBLE_EQ(utm.range_max_m, 30);
  // 1081 beams over 270° is the UTM-30LX's 0.25° step.
  World world = EmptyWorld();
  const LaserScan scan = LaserSimulator(world, Exact()).Scan(LevelLaser(), 0, 1, 0);
  EXPECT_NEAR(scan.angle_increment_rad * 180 / std::numbers::pi, 0.25, 1e-12);
  EXPECT_THROW(LaserPreset("lms-100"), Error);
}

TEST(LaserSimulator, CylinderBoxAndSphereAtKnownDistances) {
  World world = EmptyWorld();
  AddObject(world, MakePrimitive(Shape::kCylinder, {5, 0, 1}, {0.6, 0.6, 2}));  // ahead
  AddObject(world, MakePrimitive(Shape::kBox, {0, 3, 0.5}, {8, 0.2, 1}));       // wall left
  AddObject(world, MakePrimitive(Shape::kEllipsoid, {0, -4, 0.3}, {1, 1, 1}));  // ball right
  const LaserScan scan = LaserSimulator(world, Exact()).Scan(LevelLaser(), 0, 1, 0);
  const double pi = std::numbers::pi;
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, 0)], 5 - 0.3, kExactM);
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, pi / 2)], 3 - 0.1, kExactM);
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, -pi / 2)], 4 - 0.5, kExactM);
  // The beam at 135° meets the wall (y = 2.9) at x = -2.9.
  const double to_wall = 2.9 / std::sin(3 * pi / 4);
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, 3 * pi / 4)], to_wall, kExactM);
  // A beam that misses everything: no echo (REP 117: +inf).
  EXPECT_TRUE(std::isinf(scan.ranges_m[BeamAt(scan, -pi / 4)]));
}

TEST(LaserSimulator, RotatedBoxCornerFacesTheLaser) {
  World world = EmptyWorld();
  // A 2 m cube turned 45° at 6 m: the corner nearest the laser is at 6 - √2.
  AddObject(world, MakePrimitive(Shape::kBox, {6, 0, 0.5}, {2, 2, 1}, std::numbers::pi / 4));
  const LaserScan scan = LaserSimulator(world, Exact()).Scan(LevelLaser(), 0, 1, 0);
  EXPECT_NEAR(scan.ranges_m[BeamAt(scan, 0)], 6 - std::sqrt(2.0), kExactM);
}

TEST(LaserSimulator, PitchedLaserHitsFlatGroundAtHOverTanPitch) {
  World world = EmptyWorld();
  for (const double pitch_deg : {5.0, 10.0, 15.0}) {
    const double pitch = pitch_deg * std::numbers::pi / 180;
    const Eigen::Isometry3d T = MakeIsometry({0, 0, kLaserHeightM}, {0, pitch, 0});
    const LaserScan scan = LaserSimulator(world, Exact()).Scan(T, 0, 1, 0);
    const double r = scan.ranges_m[BeamAt(scan, 0)];
    // Slant range h / sin(p); its horizontal run h / tan(p).
    EXPECT_NEAR(r, kLaserHeightM / std::sin(pitch), kExactM) << pitch_deg;
    EXPECT_NEAR(r * std::cos(pitch), kLaserHeightM / std::tan(pitch), kExactM) << pitch_deg;
    // Sideways beams stay level: no ground.
    EXPECT_TRUE(std::isinf(scan.ranges_m[BeamAt(scan, std::numbers::pi / 2)])) << pitch_deg;
  }
  // Rolled to the left side down: the beam at +90° hits the ground at h / sin(roll).
  const double roll = -12 * std::numbers::pi / 180;
  const LaserScan rolled = LaserSimulator(world, Exact())
                               .Scan(MakeIsometry({0, 0, kLaserHeightM}, {roll, 0, 0}), 0, 1, 0);
  EXPECT_NEAR(rolled.ranges_m[BeamAt(rolled, std::numbers::pi / 2)],
              kLaserHeightM / std::sin(-roll), kExactM);
}

TEST(LaserSimulator, NoiseHasTheConfiguredSigma) {
  World world = EmptyWorld();
  AddObject(world, MakePrimitive(Shape::kBox, {4, 0, 0.5}, {0.2, 40, 1}));  // wall at 3.9 m
  LaserSimulatorOptions options = Exact();
  options.range_noise_sigma_m = 0.02;
  const LaserSimulator laser(world, options);
  double sum = 0, sum2 = 0;
  int n = 0;
  for (std::uint64_t k = 0; k < 20; ++k) {
    const LaserScan scan = laser.Scan(LevelLaser(), 0, 5, k);
    for (std::size_t i = BeamAt(scan, -0.5); i <= BeamAt(scan, 0.5); ++i) {
      const double expected = 3.9 / std::cos(scan.AngleOf(i));
      const double e = scan.ranges_m[i] - expected;
      sum += e;
      sum2 += e * e;
      ++n;
    }
  }
  const double mean = sum / n, sigma = std::sqrt(sum2 / n - mean * mean);
  // n ≈ 4600 samples: the sample σ is within ±3 % of 0.02 and the mean within 0.002 (≈ 7 SE).
  EXPECT_NEAR(sigma, 0.02, 0.002);
  EXPECT_NEAR(mean, 0, 0.002);
}

TEST(LaserSimulator, MixedPixelsLieBetweenTheSurfaces) {
  World world = EmptyWorld();
  AddObject(world, MakePrimitive(Shape::kBox, {2, 1.05, 0.5}, {0.2, 2, 1}));  // near, y > 0.05
  AddObject(world, MakePrimitive(Shape::kBox, {6, 0, 0.5}, {0.2, 40, 1}));    // far wall
  LaserSimulatorOptions options = Exact();
  options.mixed_pixel_probability = 1;
  const LaserScan scan = LaserSimulator(world, options).Scan(LevelLaser(), 0, 3, 0);
  int mixed = 0;
  for (std::size_t i = BeamAt(scan, -0.3); i <= BeamAt(scan, 0.3); ++i) {
    const double r = scan.ranges_m[i], c = std::cos(scan.AngleOf(i));
    // Near: the front face, or the side face just beside the edge.
    const bool near = r > 1.9 / c - kExactM && r < 2.1 / c + kExactM;
    const bool far = std::abs(r - 5.9 / c) < kExactM;
    if (!near && !far) {
      ++mixed;
      EXPECT_GT(r, 2.1 / c);
      EXPECT_LT(r, 5.9 / c);
    }
  }
  EXPECT_EQ(mixed, 1);  // exactly the beam at the edge
}

TEST(LaserSimulator, SameSeedAndIndexGiveTheSameScan) {
  World world = EmptyWorld();
  AddObject(world, MakePrimitive(Shape::kCylinder, {3, 1, 1}, {0.5, 0.5, 2}));
  const LaserSimulator laser(world, LaserSimulatorOptions{});
  EXPECT_EQ(laser.Scan(LevelLaser(), 0, 9, 4).ranges_m, laser.Scan(LevelLaser(), 0, 9, 4).ranges_m);
  EXPECT_NE(laser.Scan(LevelLaser(), 0, 9, 4).ranges_m, laser.Scan(LevelLaser(), 0, 9, 5).ranges_m);
}

}  // namespace
}  // namespace littermap::sim
