// Pose graph: a synthetic loop brings drifted poses back to the truth; the first pose stays put;
// a loop the others contradict is pruned.

#include "reconstruct/pose_graph.hpp"
#include "support/planar_errors.hpp"

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace littermap::reconstruct {
namespace {

// 40 poses around a 4 m x 4 m square, heading along the path.
std::vector<PlanarPose> Square() {
  std::vector<PlanarPose> poses;
  PlanarPose pose;
  for (int side = 0; side < 4; ++side) {
    for (int step = 0; step < 10; ++step) {
      poses.push_back(pose);
      pose = Compose(pose,
                     step == 9 ? PlanarPose{0.4, 0, std::numbers::pi / 2} : PlanarPose{0.4, 0, 0});
    }
  }
  return poses;
}

using test::MaxPositionError;

// Odometry edges with a heading bias of bias_rad per step, plus (optionally) the true loop.
std::vector<PoseGraphEdge> Edges(const std::vector<PlanarPose>& truth, double bias_rad,
                                 bool with_loop) {
  std::vector<PoseGraphEdge> edges;
  const Eigen::Matrix3d information = Eigen::Vector3d(1e4, 1e4, 1e4).asDiagonal();
  for (std::size_t i = 1; i < truth.size(); ++i) {
    PlanarPose measured = Between(truth[i - 1], truth[i]);
    measured.theta_rad += bias_rad;
    edges.push_back({i - 1, i, measured, information, false});
  }
  if (with_loop) {
    edges.push_back({0, truth.size() - 1, Between(truth.front(), truth.back()), information, true});
  }
  return edges;
}

std::vector<PlanarPose> Integrate(const std::vector<PoseGraphEdge>& edges, std::size_t n) {
  std::vector<PlanarPose> poses(n);
  for (const auto& edge : edges) {
    if (!edge.loop) poses[edge.to] = Compose(poses[edge.from], edge.T_from_to);
  }
  return poses;
}

TEST(PoseGraph, ExactEdgesFromDriftedStartRecoverTheTruth) {
  const auto truth = Square();
  auto edges = Edges(truth, 0.0, true);
  // Start from poses integrated with a biased heading: 2 degrees per step of drift.
  auto poses = Integrate(Edges(truth, 2 * std::numbers::pi / 180, false), truth.size());
  ASSERT_GT(MaxPositionError(poses, truth), 1.0);
  const PoseGraphResult result = OptimizePoseGraph(&poses, edges, {});
  ASSERT_TRUE(result.usable);
  EXPECT_LT(MaxPositionError(poses, truth), 1e-6);
  EXPECT_LT(result.final_cost, 1e-12);
  EXPECT_EQ(poses.front(), truth.front());  // held constant
}

TEST(PoseGraph, LoopReducesDriftOfBiasedOdometry) {
  const auto truth = Square();
  const double bias = 0.5 * std::numbers::pi / 180;
  auto open = Integrate(Edges(truth, bias, false), truth.size());
  auto closed = open;
  ASSERT_TRUE(OptimizePoseGraph(&closed, Edges(truth, bias, true), {}).usable);
  const double before = MaxPositionError(open, truth), after = MaxPositionError(closed, truth);
  EXPECT_GT(before, 0.3);
  EXPECT_LT(after, before / 4) << before << " -> " << after;
}

// A gyro's turn between consecutive poses as heading-only edges
// (SlamOptions::gyro_turn_sigma_rad_per_sqrt_s):
// where every match turned 0.2 degrees too far, they hold the heading the matches gave away.
std::vector<PoseGraphEdge> GyroTurns(const std::vector<PlanarPose>& truth, double sigma_rad) {
  std::vector<PoseGraphEdge> turns;
  for (std::size_t i = 1; i < truth.size(); ++i) {
    PoseGraphEdge turn;
    turn.from = i - 1;
    turn.to = i;
    turn.heading_only = true;
    turn.T_from_to.theta_rad = truth[i].theta_rad - truth[i - 1].theta_rad;
    turn.information = Eigen::Vector3d(0, 0, 1 / (sigma_rad * sigma_rad)).asDiagonal();
    turns.push_back(turn);
  }
  return turns;
}

TEST(PoseGraph, HeadingOnlyEdgesHoldTheHeadingOfBiasedMatches) {
  const auto truth = Square();
  const double bias = 0.2 * std::numbers::pi / 180;
  const auto matches = Edges(truth, bias, false);  // heading sigma 0.01 rad each
  auto drifted = Integrate(matches, truth.size());
  auto held = drifted;
  auto edges = matches;
  const auto turns = GyroTurns(truth, 0.0025);
  edges.insert(edges.end(), turns.begin(), turns.end());
  ASSERT_TRUE(OptimizePoseGraph(&held, edges, {}).usable);
  const double before = MaxPositionError(drifted, truth), after = MaxPositionError(held, truth);
  EXPECT_GT(before, 0.2);
  // Weighted 16:1 against the matches, the gyro leaves a 17th of the bias: 6 % of the error.
  EXPECT_LT(after, 0.1 * before) << before << " -> " << after;
  // Over the whole square the gyro's turns hold the heading to the truth's three quarter turns.
  EXPECT_NEAR(held.back().theta_rad - held.front().theta_rad, truth.back().theta_rad, 0.01);
}

TEST(PoseGraph, HeadingOnlyEdgesAreNoPathBetweenPoses) {
  const auto truth = Square();
  auto edges = Edges(truth, 0, false);
  PoseGraphEdge shortcut = GyroTurns({truth.front(), truth.back()}, 0.01).front();
  shortcut.to = truth.size() - 1;
  edges.push_back(shortcut);
  const std::vector<double> distance = GraphDistances(truth.size(), edges, 0);
  EXPECT_NEAR(distance.back(), 0.4 * static_cast<double>(truth.size() - 1), 1e-9);
}

TEST(PoseGraph, PruneLoopsRemovesTheLoopTheOthersContradict) {
  const auto truth = Square();
  const double bias = 0.2 * std::numbers::pi / 180;
  auto edges = Edges(truth, bias, true);
  const Eigen::Matrix3d information = Eigen::Vector3d(1e4, 1e4, 1e4).asDiagonal();
  for (const auto& [from, to] : {std::pair<std::size_t, std::size_t>{2, 38}, {5, 35}, {8, 32}}) {
    edges.push_back({from, to, Between(truth[from], truth[to]), information, true});
  }
  // A wrong loop: 0.6 m and 6 degrees off the truth.
  PlanarPose wrong = Between(truth[12], truth[27]);
  wrong = Compose(wrong, PlanarPose{0.6, 0.0, 6 * std::numbers::pi / 180});
  edges.push_back({12, 27, wrong, information, true});
  const std::size_t loops = 5;

  auto poses = Integrate(edges, truth.size());
  ASSERT_TRUE(OptimizePoseGraph(&poses, edges, {}).usable);
  const double before = MaxPositionError(poses, truth);
  const LoopPruning pruning = PruneLoops(&poses, &edges, 16.3, {});
  ASSERT_TRUE(pruning.usable);
  EXPECT_EQ(pruning.removed, 1u);
  std::size_t kept = 0;
  for (const PoseGraphEdge& edge : edges) {
    if (!edge.loop) continue;
    ++kept;
    EXPECT_FALSE(edge.from == 12 && edge.to == 27) << "the wrong loop stayed";
    EXPECT_LE(EdgeChi2(poses, edge), 16.3);
  }
  EXPECT_EQ(kept, loops - 1);
  const double after = MaxPositionError(poses, truth);
  EXPECT_LT(after, 0.05);
  EXPECT_LT(after, before / 4) << before << " -> " << after;
}

TEST(PoseGraph, PruneLoopsKeepsLoopsThatFit) {
  const auto truth = Square();
  auto edges = Edges(truth, 0.2 * std::numbers::pi / 180, true);
  auto poses = Integrate(edges, truth.size());
  ASSERT_TRUE(OptimizePoseGraph(&poses, edges, {}).usable);
  const auto optimised = poses;
  const LoopPruning pruning = PruneLoops(&poses, &edges, 16.3, {});
  EXPECT_EQ(pruning.removed, 0u);
  EXPECT_EQ(edges.size(), truth.size());  // 39 odometry edges and the loop
  EXPECT_EQ(poses, optimised);
}

TEST(PoseGraph, EdgeInformationRotatesIntoTheSourceFrame) {
  // Certain along world x only; seen from a frame turned by 90 degrees that is its y axis.
  const Eigen::Matrix3d world = Eigen::Vector3d(1e6, 1.0, 1e6).asDiagonal();
  const Eigen::Matrix3d local = EdgeInformation(world, std::numbers::pi / 2, 1e-3, 1e-3);
  EXPECT_GT(local(1, 1), 100 * local(0, 0));
}

}  // namespace
}  // namespace littermap::reconstruct

namespace littermap::reconstruct {
namespace {

// Three poses along x whose odometry says each step is 1.2 m (really 1 m), and two trunks each
// seen from all three: the range-bearing factors pull the poses back to the truth.
TEST(PoseGraph, LandmarkSightingsCorrectBiasedOdometry) {
  const std::vector<PlanarPose> truth = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const std::vector<Eigen::Vector2d> trunks = {{1, 3}, {3, -2}};
  std::vector<PlanarPose> poses = {{0, 0, 0}, {1.2, 0, 0}, {2.4, 0, 0}};
  std::vector<PoseGraphEdge> edges;
  for (std::size_t i = 0; i + 1 < poses.size(); ++i) {
    edges.push_back({i, i + 1, {1.2, 0, 0}, DiagonalInformation(0.2, 0.05), false});
  }
  LandmarkTerms landmarks;
  for (const Eigen::Vector2d& trunk : trunks) {
    landmarks.positions.push_back(trunk + Eigen::Vector2d(0.3, 0));  // where the drift put it
    for (std::size_t i = 0; i < truth.size(); ++i) {
      const Eigen::Vector2d seen(trunk.x() - truth[i].x_m, trunk.y() - truth[i].y_m);
      landmarks.terms.push_back(
          {i, landmarks.positions.size() - 1, seen, 0.02 * 0.02 * Eigen::Matrix2d::Identity()});
    }
  }
  const PoseGraphResult result = OptimizePoseGraph(&poses, edges, PoseGraphOptions{}, &landmarks);
  ASSERT_TRUE(result.usable);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_NEAR(poses[i].x_m, truth[i].x_m, 0.02) << i;
    EXPECT_NEAR(poses[i].y_m, truth[i].y_m, 0.02) << i;
  }
  for (std::size_t l = 0; l < trunks.size(); ++l) {
    EXPECT_LT((landmarks.positions[l] - trunks[l]).norm(), 0.02) << l;
  }
  // At the solution every sighting fits: chi-squared far below its 99 % bound (9.21).
  for (const LandmarkTerm& term : landmarks.terms) {
    EXPECT_LT(LandmarkChi2(poses[term.pose], landmarks.positions[term.landmark], term), 1.0);
  }
}

}  // namespace
}  // namespace littermap::reconstruct
