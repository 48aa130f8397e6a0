// Map sharpness on scans of a known room: the true poses draw the walls thinnest, and pose noise
// of the size SLAM errors have makes the count grow; the rules for which scans and echoes are
// drawn, and the refusals.

#include "eval/map_sharpness.hpp"

#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "support/room_run.hpp"

namespace littermap::eval {
namespace {

using test::kBaseLaser;
using test::kDeg;
using test::Perturbed;
using test::RoomRun;
using test::RoomScans;

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
  const std::vector<StampedPose> trajectory = {
      StampedPoseFromPlanar(scan.stamp_ns + 10'000'000, {0, 0, 0}),
      StampedPoseFromPlanar(scan.stamp_ns - 3'000'000'000, {0, 0, 0})};
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
  const std::vector<StampedPose> other = {StampedPoseFromPlanar(999'000'000'000LL, {0, 0, 0})};
  EXPECT_THROW(MeasureMapSharpness(run.scans, kBaseLaser, other), BadInputError);
  MapSharpnessOptions bad;
  bad.cell_size_m = 0;
  EXPECT_THROW(MeasureMapSharpness(run.scans, kBaseLaser, run.truth, bad), UsageError);
  bad = {};
  bad.max_range_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(MeasureMapSharpness(run.scans, kBaseLaser, run.truth, bad), UsageError);
  // A pose far outside any map draws nothing rather than wrapping around.
  const std::vector<StampedPose> huge = {
      StampedPoseFromPlanar(run.scans[0].stamp_ns, {1e12, 0, 0})};
  EXPECT_EQ(MeasureMapSharpness({run.scans[0]}, kBaseLaser, huge).occupied_cells, 0u);
}

}  // namespace
}  // namespace littermap::eval
