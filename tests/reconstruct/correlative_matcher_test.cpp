// Correlative matcher: finds a pose metres and degrees away from the initial guess in the
// synthetic room (beyond ICP's reach), and its branch and bound agrees with exhaustive search.

#include "reconstruct/correlative_matcher.hpp"

#include <cmath>
#include <numbers>

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
  // The branch and bound expands only a fraction of the fine poses.
  const double fine_poses = static_cast<double>(result.coarse_candidates) * 64;
  EXPECT_LT(static_cast<double>(result.fine_evaluations), 0.1 * fine_poses);
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

TEST(CorrelativeMatcher, EmptyInputsFindNothing) {
  const Points2 room = RoomPoints({3, 2, 0});
  EXPECT_FALSE(MatchCorrelative({}, room, {}, 1, 0.1, {}).found);
  EXPECT_FALSE(MatchCorrelative(room, {}, {}, 1, 0.1, {}).found);
}

}  // namespace
}  // namespace littermap::reconstruct
