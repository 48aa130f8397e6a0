// The final scan alignment on synthetic scenes with known poses: drift is taken out against the
// scans, a corridor's open direction is left to the odometry, the two sides of a wall are not
// paired, scans between held key frames are brought onto their walls, and bad input is refused.

#include "reconstruct/scan_alignment.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "reconstruct/pose_graph.hpp"
#include "support/angles.hpp"
#include "support/planar_errors.hpp"
#include "synthetic_world.hpp"

namespace littermap::reconstruct {
namespace {

using test::kDeg;

std::vector<KeyFrame> KeyFramesSeenIn(const std::vector<test::Segment>& walls,
                                      const std::vector<PlanarPose>& truth) {
  std::vector<KeyFrame> frames;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    KeyFrame frame;
    frame.scan_index = i;
    frame.T_world_base = truth[i];
    frame.points_base =
        VoxelDownsample(ScanToPoints(test::ScanFrom(walls, truth[i]), {}, {}).points_base, 0.05);
    frame.normals_base = EstimateNormals(frame.points_base, IcpOptions{});
    frames.push_back(std::move(frame));
  }
  return frames;
}

// Edges between consecutive poses with the given relative motions and standard deviations.
std::vector<PoseGraphEdge> Odometry(const std::vector<PlanarPose>& poses, double sigma_m,
                                    double sigma_rad) {
  std::vector<PoseGraphEdge> edges;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    edges.push_back({i - 1, i, Between(poses[i - 1], poses[i]),
                     DiagonalInformation(sigma_m, sigma_rad), false});
  }
  return edges;
}

using test::MaxPositionError;

double MaxHeadingError(const std::vector<PlanarPose>& a, const std::vector<PlanarPose>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(WrapAngle(a[i].theta_rad - b[i].theta_rad)));
  }
  return worst;
}

// A loop around the room's pillar, back to where it started.
std::vector<PlanarPose> LoopAroundThePillar() {
  std::vector<PlanarPose> poses;
  for (int i = 0; i <= 24; ++i) {
    const double a = 2 * std::numbers::pi * i / 24;
    poses.push_back({5.5 + 3.5 * std::cos(a), 3.3 + 2.0 * std::sin(a), a + std::numbers::pi / 2});
  }
  return poses;
}

TEST(ScanAlignment, DriftIsTakenOutAgainstTheScans) {
  const auto room = test::Room();
  const std::vector<PlanarPose> truth = LoopAroundThePillar();
  // Odometry that turns 0.25 degrees too far and drives 1 % too long every step: 0.2 m and 6
  // degrees off by the end of the loop, the poses as it integrates them.
  std::vector<PlanarPose> drifted = {truth.front()};
  for (std::size_t i = 1; i < truth.size(); ++i) {
    PlanarPose step = Between(truth[i - 1], truth[i]);
    step = {step.x_m * 1.01, step.y_m * 1.01, step.theta_rad + 0.25 * kDeg};
    drifted.push_back(Compose(drifted.back(), step));
  }
  ASSERT_GT(MaxPositionError(drifted, truth), 0.15);
  std::vector<PlanarPose> poses = drifted;
  const ScanAlignmentResult result =
      AlignScans(KeyFramesSeenIn(room, truth), Odometry(drifted, 0.05, 1 * kDeg), &poses, {});
  ASSERT_TRUE(result.usable);
  EXPECT_EQ(result.rounds, 4);
  EXPECT_GT(result.pairs_matched, truth.size());  // the predecessors and the loop's revisits
  EXPECT_LT(result.final_cost, result.initial_cost);
  // Noiseless scans: back on the truth to a few millimetres (the odometry's bias pulls a little).
  EXPECT_LT(MaxPositionError(poses, truth), 0.01);
  EXPECT_LT(MaxHeadingError(poses, truth), 0.1 * kDeg);
}

// Two parallel walls 2 m apart and 200 m long, their ends out of the laser's range: nothing
// along them to match.
std::vector<test::Segment> CorridorWalls() {
  return {{{-100, 0}, {100, 0}}, {{-100, 2}, {100, 2}}};
}

TEST(ScanAlignment, TheOdometryKeepsWhatACorridorLeavesOpen) {
  std::vector<PlanarPose> truth;
  for (int i = 0; i < 10; ++i) truth.push_back({0.5 * i, 1.0, 0});
  // Off by 5 cm across the corridor and 0.5 degrees here and there, and 20 cm along it.
  std::vector<PlanarPose> poses = truth;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    poses[i].x_m += 0.2;
    poses[i].y_m += (i % 2 == 0 ? 0.05 : -0.05);
    poses[i].theta_rad += (i % 3 == 0 ? 0.5 : -0.5) * kDeg;
  }
  // The odometry is right, but weak against the walls.
  const ScanAlignmentResult result = AlignScans(KeyFramesSeenIn(CorridorWalls(), truth),
                                                Odometry(truth, 0.05, 1 * kDeg), &poses, {});
  ASSERT_TRUE(result.usable);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_NEAR(poses[i].y_m, truth[i].y_m, 0.005) << i;  // the walls decide across
    EXPECT_NEAR(poses[i].theta_rad, truth[i].theta_rad, 0.05 * kDeg) << i;
    // Along the corridor only the odometry speaks, and it is right.
    EXPECT_NEAR(poses[i].x_m, truth[i].x_m, 0.005) << i;
  }
}

TEST(ScanAlignment, TheTwoSidesOfAWallAreNotPaired) {
  // A wall 10 cm thick and 8 m long, seen from 1 m on either side.
  const std::vector<test::Segment> wall = {
      {{-4, 0}, {4, 0}}, {{4, 0}, {4, 0.1}}, {{4, 0.1}, {-4, 0.1}}, {{-4, 0.1}, {-4, 0}}};
  const std::vector<PlanarPose> truth = {{0, -1, 0}, {0, 1.1, 0}};
  std::vector<PlanarPose> poses = truth;
  const ScanAlignmentResult result =
      AlignScans(KeyFramesSeenIn(wall, truth), Odometry(truth, 0.1, 5 * kDeg), &poses, {});
  ASSERT_TRUE(result.usable);
  // Paired, the far side would pull the second pose 10 cm towards the first.
  EXPECT_EQ(result.pairs_matched, 0u);
  EXPECT_NEAR(poses[1].y_m, 1.1, 1e-6);
}

TEST(ScanAlignment, ScansBetweenHeldKeyFramesLandOnTheirWalls) {
  const auto room = test::Room();
  const std::vector<PlanarPose> truth = LoopAroundThePillar();
  // Every fourth pose is a key frame, held where it truly is; the scans between are off by up to
  // 4 cm and 0.6 degrees, as a tracker's match against a local map leaves them.
  std::vector<bool> held(truth.size(), false);
  std::vector<PlanarPose> poses = truth;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    held[i] = i % 4 == 0;
    if (held[i]) continue;
    poses[i].x_m += (i % 2 == 0 ? 0.04 : -0.03);
    poses[i].y_m += (i % 3 == 0 ? -0.04 : 0.02);
    poses[i].theta_rad += (i % 2 == 0 ? 0.6 : -0.4) * kDeg;
  }
  ASSERT_GT(MaxPositionError(poses, truth), 0.04);
  const std::vector<PlanarPose> given = poses;
  // Held to their neighbours by the (wrong) steps between the given poses, weakly.
  const ScanAlignmentResult result = AlignScansToHeld(
      KeyFramesSeenIn(room, truth), Odometry(given, 0.05, 2 * kDeg), held, &poses, {});
  ASSERT_TRUE(result.usable);
  EXPECT_EQ(result.rounds, 4);
  // Each free scan with the held frames before and after it, and revisits of other key frames.
  EXPECT_GE(result.pairs_matched, 2 * 18u);
  EXPECT_LT(result.final_cost, result.initial_cost);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (held[i]) {
      EXPECT_EQ(poses[i].x_m, given[i].x_m) << i;
      EXPECT_NEAR(WrapAngle(poses[i].theta_rad - given[i].theta_rad), 0, 1e-12) << i;
    }
  }
  // Noiseless scans: on the truth to a few millimetres, whatever the steps held them to.
  EXPECT_LT(MaxPositionError(poses, truth), 0.005);
  EXPECT_LT(MaxHeadingError(poses, truth), 0.1 * kDeg);

  std::vector<bool> short_flags(3, true);
  EXPECT_THROW(AlignScansToHeld(KeyFramesSeenIn(room, truth), {}, short_flags, &poses, {}),
               InternalError);
}

TEST(ScanAlignment, BadInputIsRefused) {
  ScanAlignmentOptions options;
  options.max_correspondence_distances_m = {};
  EXPECT_THROW(options.Validate(), UsageError);
  options = {};
  options.point_sigma_m = 0;
  EXPECT_THROW(options.Validate(), UsageError);
  options = {};
  options.max_correspondence_distances_m = {0.3, 0.05};  // under 3 sigmas of 3 cm
  EXPECT_THROW(options.Validate(), UsageError);
  options = {};
  options.max_iterations_per_round = 0;
  EXPECT_THROW(options.Validate(), UsageError);

  const std::vector<PlanarPose> truth = {{1, 1, 0}, {1.5, 1, 0}};
  const auto frames = KeyFramesSeenIn(test::Room(), truth);
  std::vector<PlanarPose> one = {truth[0]};
  EXPECT_THROW(AlignScans(frames, {}, &one, {}), InternalError);
  std::vector<PlanarPose> poses = truth;
  const std::vector<PoseGraphEdge> dangling = {{0, 5, {}, Eigen::Matrix3d::Identity(), false}};
  EXPECT_THROW(AlignScans(frames, dangling, &poses, {}), InternalError);
  // A single key frame has nothing to align against.
  const ScanAlignmentResult single = AlignScans({frames[0]}, {}, &one, {});
  EXPECT_TRUE(single.usable);
  EXPECT_EQ(single.rounds, 0);
}

}  // namespace
}  // namespace littermap::reconstruct
