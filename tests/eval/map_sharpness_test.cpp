// Map sharpness on scans of a known room: the true poses draw the walls thinnest, and pose noise
// of the size SLAM errors have makes the count grow; the rules for which scans and echoes are
// drawn, and the refusals.

#include "eval/map_sharpness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace littermap::eval {
namespace {

// A square room [2 cm, 10.02 m]^2: its walls run through the middle of 5 cm cells, not along
// cell borders (where rounding would split a wall over two rows).
constexpr double kWallM = 0.02;
constexpr double kRoomM = 10;
constexpr double kDeg = std::numbers::pi / 180;

StampedPose Stamped(TimestampNs stamp_ns, const PlanarPose& pose) {
  StampedPose stamped;
  stamped.stamp_ns = stamp_ns;
  stamped.position_m = {pose.x_m, pose.y_m, 0};
  stamped.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(pose.theta_rad, Eigen::Vector3d::UnitZ()));
  return stamped;
}

// Range from (x, y) along world angle a to the room's walls.
double RangeToWalls(double x, double y, double a) {
  const double c = std::cos(a), s = std::sin(a);
  double range = std::numeric_limits<double>::infinity();
  if (c > 1e-12) range = std::min(range, (kWallM + kRoomM - x) / c);
  if (c < -1e-12) range = std::min(range, (kWallM - x) / c);
  if (s > 1e-12) range = std::min(range, (kWallM + kRoomM - y) / s);
  if (s < -1e-12) range = std::min(range, (kWallM - y) / s);
  return range;
}

// 360 beams over 360° from laser pose T_world_laser, stamped at stamp_ns.
LaserScan ScanFrom(const PlanarPose& T_world_laser, TimestampNs stamp_ns) {
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

const PlanarPose kBaseLaser{0.2, 0.05, 0.1};

// 100 scans along a loop inside the room, 0.1 s apart, the laser mounted off centre and turned.
RoomScans RoomRun() {
  RoomScans run;
  for (int k = 0; k < 100; ++k) {
    const double phase = 2 * std::numbers::pi * k / 100;
    const PlanarPose T_world_base{5 + 3 * std::cos(phase), 5 + 3 * std::sin(phase),
                                  phase + std::numbers::pi / 2};
    const TimestampNs stamp_ns = 1'000'000'000LL + k * 100'000'000LL;
    run.truth.push_back(Stamped(stamp_ns, T_world_base));
    run.scans.push_back(ScanFrom(Compose(T_world_base, kBaseLaser), stamp_ns));
  }
  return run;
}

std::vector<StampedPose> Perturbed(const std::vector<StampedPose>& poses, double sigma_m,
                                   double sigma_rad) {
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  std::vector<StampedPose> perturbed;
  for (const StampedPose& pose : poses) {
    const double yaw = std::atan2(pose.orientation.toRotationMatrix()(1, 0),
                                  pose.orientation.toRotationMatrix()(0, 0));
    perturbed.push_back(Stamped(pose.stamp_ns, {pose.position_m.x() + sigma_m * normal(random),
                                                pose.position_m.y() + sigma_m * normal(random),
                                                yaw + sigma_rad * normal(random)}));
  }
  return perturbed;
}

TEST(MapSharpness, TruePosesDrawTheThinnestWalls) {
  const RoomScans run = RoomRun();
  const MapSharpness truth = MeasureMapSharpness(run.scans, kBaseLaser, run.truth);
  EXPECT_EQ(truth.scans, 100u);
  EXPECT_EQ(truth.scans_drawn, 100u);
  EXPECT_EQ(truth.echoes_drawn, 36000u);
  // Each wall lies within one row of 5 cm cells and spans 201 of them, corners shared: 800.
  EXPECT_EQ(truth.occupied_cells, 800u);

  // Pose errors of 2 cm and 0.5°, a good SLAM result's, already widen the walls; a wrong
  // mounting does too.
  const MapSharpness noisy =
      MeasureMapSharpness(run.scans, kBaseLaser, Perturbed(run.truth, 0.02, 0.5 * kDeg));
  EXPECT_GT(noisy.occupied_cells, 3 * truth.occupied_cells / 2);
  const MapSharpness mounted_wrong = MeasureMapSharpness(run.scans, PlanarPose{0, 0, 0}, run.truth);
  EXPECT_GT(mounted_wrong.occupied_cells, 3 * truth.occupied_cells / 2);
  // And the count grows with the error.
  const MapSharpness noisier =
      MeasureMapSharpness(run.scans, kBaseLaser, Perturbed(run.truth, 0.05, 1.5 * kDeg));
  RecordProperty("cells_true_noisy_noisier_mounted",
                 std::to_string(truth.occupied_cells) + " " + std::to_string(noisy.occupied_cells) +
                     " " + std::to_string(noisier.occupied_cells) + " " +
                     std::to_string(mounted_wrong.occupied_cells));
  EXPECT_GT(noisier.occupied_cells, noisy.occupied_cells);
}

TEST(MapSharpness, OnlyScansWithAPoseAndValidNearEchoesAreDrawn) {
  LaserScan scan;
  scan.stamp_ns = 1'000'000'000;
  scan.angle_min_rad = 0;
  scan.angle_increment_rad = std::numbers::pi / 2;
  scan.range_min_m = 0.1;
  scan.range_max_m = 30;
  // 1 m ahead, 2 m to the left; then no echo (+inf), NaN, too close, beyond max_range_m (20 m).
  scan.ranges_m = {1.0f, 2.0f, std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::quiet_NaN()};
  LaserScan far = scan;
  far.ranges_m = {0.05f, 25.0f};
  LaserScan unposed = scan;
  unposed.stamp_ns += 500'000'000;  // 0.5 s from the nearest pose

  // Poses 10 ms off the scans' stamps (within the default 20 ms).
  const std::vector<StampedPose> trajectory = {Stamped(scan.stamp_ns + 10'000'000, {0, 0, 0}),
                                               Stamped(scan.stamp_ns - 3'000'000'000, {0, 0, 0})};
  const MapSharpness result = MeasureMapSharpness({scan, far, unposed}, PlanarPose{}, trajectory);
  EXPECT_EQ(result.scans, 3u);
  EXPECT_EQ(result.scans_drawn, 2u);
  EXPECT_EQ(result.echoes_drawn, 2u);
  EXPECT_EQ(result.occupied_cells, 2u);

  // The same echo twice is one cell; a coarser grid merges more.
  MapSharpnessOptions coarse;
  coarse.cell_size_m = 5;
  EXPECT_EQ(MeasureMapSharpness({scan, scan}, PlanarPose{}, trajectory, coarse).occupied_cells, 1u);
}

TEST(MapSharpness, RefusesWhatCannotBeMeasured) {
  const RoomScans run = RoomRun();
  EXPECT_THROW(MeasureMapSharpness(run.scans, kBaseLaser, {}), BadInputError);
  // A trajectory of another time: no scan has a pose.
  const std::vector<StampedPose> other = {Stamped(999'000'000'000LL, {0, 0, 0})};
  EXPECT_THROW(MeasureMapSharpness(run.scans, kBaseLaser, other), BadInputError);
  MapSharpnessOptions bad;
  bad.cell_size_m = 0;
  EXPECT_THROW(MeasureMapSharpness(run.scans, kBaseLaser, run.truth, bad), UsageError);
  bad = {};
  bad.max_range_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(MeasureMapSharpness(run.scans, kBaseLaser, run.truth, bad), UsageError);
  // A pose far outside any map draws nothing rather than wrapping around.
  const std::vector<StampedPose> huge = {Stamped(run.scans[0].stamp_ns, {1e12, 0, 0})};
  EXPECT_EQ(MeasureMapSharpness({run.scans[0]}, kBaseLaser, huge).occupied_cells, 0u);
}

}  // namespace
}  // namespace littermap::eval
