// Correlative matcher: finds a pose metres and degrees away from the initial guess in the
// synthetic room (beyond ICP's reach), and its branch and bound finds the best pose that scoring
// every pose of the window finds.

#include "reconstruct/correlative_matcher.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "reconstruct/icp_matcher.hpp"
#include "support/angles.hpp"
#include "synthetic_world.hpp"

namespace littermap::reconstruct {
namespace {

using test::kDeg;

using test::RoomPoints;

TEST(CorrelativeMatcher, FindsAPoseFarFromTheGuess) {
  // Target: the room seen from (3, 2, 0), in the world frame. Source: seen from (6.5, 4.2, 0.2).
  const PlanarPose T_world_target{3, 2, 0};
  const PlanarPose T_world_source{6.5, 4.2, 0.2};
  const Points2 target = TransformPoints(T_world_target, RoomPoints(T_world_target));
  const Points2 source = RoomPoints(T_world_source);
  const PlanarPose guess{4.5, 3.0, 0.05};  // 2.3 m and 8.6 degrees off
  const CorrelativeResult result = MatchCorrelative(source, target, guess, 3.0, 0.3, {});
  ASSERT_TRUE(result.found);
  // Within a cell and about a rotation step (0.1 m; 0.1 m at the farthest point used, 12 m,
  // is 0.48 degrees; measured 0.55 degrees off).
  EXPECT_NEAR(result.T_target_source.x_m, T_world_source.x_m, 0.1);
  EXPECT_NEAR(result.T_target_source.y_m, T_world_source.y_m, 0.1);
  EXPECT_NEAR(result.T_target_source.theta_rad, T_world_source.theta_rad, 1 * kDeg);
  // Walls hidden from the target's viewpoint and the cell quantisation keep it from 1 (0.61).
  EXPECT_GT(result.score, 0.5);
  // The branch and bound scores only a few per cent of the window's poses (measured 3.4 %).
  EXPECT_LT(static_cast<double>(result.fine_evaluations + result.bound_evaluations),
            0.05 * static_cast<double>(result.window_poses));
  // ICP from there lands on the truth; from the guess alone it does not get there.
  const IcpOptions icp;
  const IcpTarget icp_target(target, icp);
  const IcpResult refined = MatchIcp(source, icp_target, result.T_target_source, icp);
  ASSERT_TRUE(refined.converged);
  EXPECT_NEAR(refined.T_target_source.x_m, T_world_source.x_m, 0.01);
  EXPECT_NEAR(refined.T_target_source.y_m, T_world_source.y_m, 0.01);
  EXPECT_NEAR(refined.T_target_source.theta_rad, T_world_source.theta_rad, 0.1 * kDeg);
  const IcpResult from_guess = MatchIcp(source, icp_target, guess, icp);
  EXPECT_GT(std::hypot(from_guess.T_target_source.x_m - T_world_source.x_m,
                       from_guess.T_target_source.y_m - T_world_source.y_m),
            0.2);
}

// Depth 0 scores every pose of the window: the branch and bound must find a pose as good, for
// every depth, also where the best pose puts scan points left of and below the target's field
// (a window that starts outside the field still bounds the cells it reaches into).
TEST(CorrelativeMatcher, BranchAndBoundScoresAsHighAsScoringEveryPose) {
  const PlanarPose T_world_target{3, 2, 0};
  const Points2 room = TransformPoints(T_world_target, RoomPoints(T_world_target));
  // The target's part of the room right of x = 4 and above y = 3: the scan's other walls fall
  // left of and below its field.
  Points2 corner;
  for (const Eigen::Vector2d& p : room) {
    if (p.x() > 4 && p.y() > 3) corner.push_back(p);
  }
  ASSERT_GT(corner.size(), 50u);
  for (const Points2* target : std::vector<const Points2*>{&room, &corner}) {
    for (const PlanarPose& guess : {PlanarPose{4.5, 3.0, 0.05}, PlanarPose{3.4, 1.8, -0.1}}) {
      const Points2 source = RoomPoints({3.9, 2.4, 0.08});
      CorrelativeOptions every_pose;
      every_pose.max_branch_and_bound_depth = 0;
      const CorrelativeResult reference =
          MatchCorrelative(source, *target, guess, 1.2, 0.15, every_pose);
      ASSERT_TRUE(reference.found);
      EXPECT_EQ(reference.fine_evaluations, reference.window_poses);
      for (const int depth : {1, 3, 7}) {
        CorrelativeOptions options;
        options.max_branch_and_bound_depth = depth;
        const CorrelativeResult result =
            MatchCorrelative(source, *target, guess, 1.2, 0.15, options);
        ASSERT_TRUE(result.found);
        EXPECT_EQ(result.score, reference.score) << "depth " << depth;
        EXPECT_LT(result.fine_evaluations, reference.fine_evaluations);
        // The same pose unless another scores exactly as high.
        EXPECT_NEAR(result.T_target_source.x_m, reference.T_target_source.x_m, 1e-9);
        EXPECT_NEAR(result.T_target_source.y_m, reference.T_target_source.y_m, 1e-9);
        EXPECT_NEAR(result.T_target_source.theta_rad, reference.T_target_source.theta_rad, 1e-9);
      }
      // A minimum score under the best prunes more and finds the same pose; above it, nothing.
      CorrelativeOptions with_minimum;
      with_minimum.min_score = reference.score - 0.05;
      const CorrelativeResult pruned =
          MatchCorrelative(source, *target, guess, 1.2, 0.15, with_minimum);
      ASSERT_TRUE(pruned.found);
      EXPECT_EQ(pruned.score, reference.score);
      with_minimum.min_score = reference.score + 0.01;
      const CorrelativeResult none =
          MatchCorrelative(source, *target, guess, 1.2, 0.15, with_minimum);
      EXPECT_FALSE(none.found);
      EXPECT_EQ(none.score, 0);
    }
  }
}

TEST(CorrelativeMatcher, EmptyInputsFindNothing) {
  const Points2 room = RoomPoints({3, 2, 0});
  EXPECT_FALSE(MatchCorrelative({}, room, {}, 1, 0.1, {}).found);
  EXPECT_FALSE(MatchCorrelative(room, {}, {}, 1, 0.1, {}).found);
}

}  // namespace
}  // namespace littermap::reconstruct
