// Moving echoes: brought into an earlier scan's frame by the odometry, static echoes land on that
// scan's echoes and an arc that follows the robot (the scan plane cutting a hill ahead) does not.

#include "reconstruct/moving_echo_filter.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

constexpr double kScanPeriodS = 0.025;  // 40 Hz
constexpr double kSpeedMps = 0.7;

// Trunks of 0.3 m, sampled every 2 cm on the half facing the robot's path, in the world.
Points2 Trunks() {
  Points2 points;
  for (const Eigen::Vector2d& centre : {Eigen::Vector2d(4, 3), Eigen::Vector2d(7, -2.5),
                                        Eigen::Vector2d(10, 4), Eigen::Vector2d(2, -3)}) {
    for (int k = 0; k < 24; ++k) {
      const double a =
          std::numbers::pi * (0.5 + k / 24.0) + (centre.y() < 0 ? std::numbers::pi : 0);
      points.push_back(centre + 0.15 * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
  }
  return points;
}

// An arc of the given number of points at 12 m ahead of the robot, in the base frame: it moves
// with the robot.
Points2 FollowingArc(int count) {
  Points2 points;
  for (int k = 0; k < count; ++k) {
    const double a = -0.6 + 1.2 * k / (count - 1);
    points.push_back(12 * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return points;
}

struct Step {
  TimestampNs stamp_ns;
  PlanarPose T_odom_base;  // the odometry is the truth here
  Points2 points_base;
};

// Scan i of a robot driving along +x, seeing the trunks and an arc of arc_points.
Step ScanAt(int i, int arc_points) {
  const double t = i * kScanPeriodS;
  const PlanarPose T_world_base{kSpeedMps * t, 0.05 * t, 0.02 * t};
  Points2 points = TransformPoints(Inverse(T_world_base), Trunks());
  for (const Eigen::Vector2d& p : FollowingArc(arc_points)) points.push_back(p);
  return {FromSeconds(t), T_world_base, points};
}

TEST(MovingEchoFilter, StaticEchoesAllPass) {
  MovingEchoFilter filter({});
  for (int i = 0; i < 40; ++i) {
    Step step = ScanAt(i, 0);
    const std::size_t count = step.points_base.size();
    const MovingEchoResult result =
        filter.Filter(step.stamp_ns, step.T_odom_base, std::move(step.points_base));
    EXPECT_EQ(result.moving, 0u) << "scan " << i;
    EXPECT_FALSE(result.given_up);
    EXPECT_EQ(result.points_base.size(), count);
  }
}

TEST(MovingEchoFilter, AnArcThatFollowsTheRobotIsDropped) {
  MovingEchoFilter filter({});
  const int arc = 30;  // 30 of 126 echoes: under the half that gives a scan up
  for (int i = 0; i < 40; ++i) {
    Step step = ScanAt(i, arc);
    const MovingEchoResult result =
        filter.Filter(step.stamp_ns, step.T_odom_base, std::move(step.points_base));
    EXPECT_FALSE(result.given_up);
    if (i * kScanPeriodS < 0.25) {  // nothing a quarter of a second older yet: all pass
      EXPECT_EQ(result.moving, 0u) << "scan " << i;
      continue;
    }
    // The arc moved 0.175 m with the robot since the scan compared with: every point of it
    // goes, every trunk point stays.
    EXPECT_EQ(result.moving, static_cast<std::size_t>(arc)) << "scan " << i;
    EXPECT_EQ(result.points_base.size(), Trunks().size()) << "scan " << i;
    for (const Eigen::Vector2d& p : result.points_base) EXPECT_LT(p.norm(), 11.0);
  }
}

TEST(MovingEchoFilter, AScanMostlyOfMovingEchoesIsGivenUp) {
  MovingEchoFilter filter({});
  MovingEchoResult last;
  for (int i = 0; i <= 20; ++i) {
    Step step = ScanAt(i, 200);  // 200 of 296 echoes follow the robot: over half
    last = filter.Filter(step.stamp_ns, step.T_odom_base, std::move(step.points_base));
  }
  EXPECT_TRUE(last.given_up);
  EXPECT_EQ(last.moving, 200u);
  EXPECT_EQ(last.points_base.size(), Trunks().size());  // the static echoes, for the map
}

TEST(MovingEchoFilter, ANewlySeenObjectIsNotMoving) {
  // An echo far from everything the earlier scan saw is new to the view, not moved.
  MovingEchoFilter filter({});
  for (int i = 0; i <= 10; ++i) {
    Step step = ScanAt(i, 0);
    if (i == 10) step.points_base.push_back({3, 9});
    const MovingEchoResult result =
        filter.Filter(step.stamp_ns, step.T_odom_base, std::move(step.points_base));
    EXPECT_EQ(result.moving, 0u);
  }
}

// Scan i of the robot of ScanAt, seeing the trunks and, beside its path, the ridge of a hill that
// the robot drives obliquely across: where the scan plane cuts the slope, a line of echoes
// parallel to the path, 2 m behind to 2 m ahead of the robot, that creeps towards the path by
// 0.15 m every second (y = 6 - 0.15 t in the world) while sliding along itself.
Step ScanBesideACreepingRidge(int i) {
  const double t = i * kScanPeriodS;
  Step step = ScanAt(i, 0);
  const PlanarPose T_base_world = Inverse(step.T_odom_base);
  for (double ahead = -2; ahead <= 2; ahead += 0.02) {
    step.points_base.push_back(
        Transform(T_base_world, Eigen::Vector2d(step.T_odom_base.x_m + ahead, 6 - 0.15 * t)));
  }
  return step;
}

TEST(MovingEchoFilter, ARidgeThatCreepsTowardsThePathIsDroppedOverASecond) {
  // Over a quarter of a second the ridge moves 4 cm across itself, within the tolerance of a
  // static echo 6 m away; over a second, 15 cm: beyond it.
  for (const double long_interval_s : {0.0, MovingEchoFilterOptions{}.long_interval_s}) {
    MovingEchoFilterOptions options;
    options.long_interval_s = long_interval_s;
    MovingEchoFilter filter(options);
    for (int i = 0; i < 80; ++i) {
      Step step = ScanBesideACreepingRidge(i);
      const PlanarPose T_world_base = step.T_odom_base;
      const MovingEchoResult result =
          filter.Filter(step.stamp_ns, step.T_odom_base, std::move(step.points_base));
      std::size_t ridge_kept = 0;
      std::size_t trunks_kept = 0;
      for (const Eigen::Vector2d& p : result.points_base) {
        ++(Transform(T_world_base, p).y() > 5 ? ridge_kept : trunks_kept);
      }
      EXPECT_EQ(trunks_kept, Trunks().size()) << "scan " << i;
      if (long_interval_s == 0 || i * kScanPeriodS < 1.0) {
        // All of its 201 echoes but the few at its front end, beside the earlier front end.
        EXPECT_GE(ridge_kept, 190u) << "scan " << i << ", long interval " << long_interval_s;
        EXPECT_FALSE(result.given_up);
      } else {
        // All of it but the few echoes ahead of what the robot saw a second ago, new to the view.
        EXPECT_LE(ridge_kept, 10u) << "scan " << i;
        EXPECT_TRUE(result.given_up);  // most of the scan's echoes moved
      }
    }
  }
}

TEST(MovingEchoFilter, RejectsBadOptions) {
  MovingEchoFilterOptions options;
  options.max_shift_m = options.static_tolerance_m;
  EXPECT_THROW(MovingEchoFilter{options}, UsageError);
  options = {};
  options.max_moving_fraction = 0;
  EXPECT_THROW(MovingEchoFilter{options}, UsageError);
  options = {};
  options.min_interval_s = 0;
  EXPECT_THROW(MovingEchoFilter{options}, UsageError);
  options = {};
  options.long_interval_s = -1;
  EXPECT_THROW(MovingEchoFilter{options}, UsageError);
}

}  // namespace
}  // namespace littermap::reconstruct
