// The tracker fuses each match with the prediction: where a scan leaves a direction open, the
// prediction holds the pose there instead of letting the matcher slide along it.

#include "reconstruct/tracker.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "reconstruct/keyframe_map.hpp"
#include "reconstruct/scan_points.hpp"
#include "synthetic_world.hpp"

namespace littermap::reconstruct {
namespace {

// A round column (a 72-gon, radius 1 m): it looks the same from every point of a circle around
// its centre, so a scan of it alone fixes range and bearing to the centre but not the robot's
// place on that circle.
std::vector<testing::Segment> Column() {
  const Eigen::Vector2d centre(4, 2.5);
  std::vector<testing::Segment> walls;
  const int sides = 72;
  for (int i = 0; i < sides; ++i) {
    const double a = 2 * std::numbers::pi * i / sides;
    const double b = 2 * std::numbers::pi * (i + 1) / sides;
    walls.push_back({centre + Eigen::Vector2d(std::cos(a), std::sin(a)),
                     centre + Eigen::Vector2d(std::cos(b), std::sin(b))});
  }
  return walls;
}

// Drives 8 m along x past the column with exact odometry and noisy ranges; returns the largest
// position error of the tracked poses.
double LargestErrorPassingColumn(const TrackerOptions& options) {
  KeyFrameMap map(options.key_frames, options.icp);
  Tracker tracker(options, &map);
  std::mt19937_64 engine(11);
  std::normal_distribution<double> range_noise(0, 0.02);
  double largest = 0;
  for (int i = 0; i <= 160; ++i) {
    const PlanarPose truth{0.05 * i, 0, 0};
    LaserScan scan = testing::ScanFrom(Column(), truth);
    for (float& r : scan.ranges_m) {
      if (r < scan.range_max_m) r = static_cast<float>(r + range_noise(engine));
    }
    scan.stamp_ns = static_cast<TimestampNs>(i) * 100'000'000;
    TrackInput input;
    input.stamp_ns = scan.stamp_ns;
    input.T_odom_base = truth;
    input.points_base = VoxelDownsample(ScanToPoints(scan, {}, {}).points_base, 0.05);
    const TrackStep step = tracker.Track(static_cast<std::size_t>(i), input);
    largest = std::max(largest, std::hypot(step.T_world_base.x_m - truth.x_m,
                                           step.T_world_base.y_m - truth.y_m));
  }
  return largest;
}

TEST(Tracker, PredictionHoldsThePoseWhereTheScanLeavesItOpen) {
  // Exact odometry: all error comes from the matches. With a prediction too weak to matter the
  // noisy column scans let the pose wander around the column (measured 2.7 m over 8 m); fused
  // with the odometry since the last key frame it stays close (measured 0.24 m: each key frame
  // still starts from a pose that slid a little).
  TrackerOptions without;
  without.odometry_sigma_m = 100;
  without.odometry_sigma_rad = 100;
  const double wandered_m = LargestErrorPassingColumn(without);
  EXPECT_GT(wandered_m, 1.0);
  EXPECT_LT(LargestErrorPassingColumn(TrackerOptions{}), wandered_m / 5);
}

}  // namespace
}  // namespace littermap::reconstruct
