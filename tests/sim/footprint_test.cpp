// Footprints of small objects: their extent from above, and when two of them share space.

#include "sim/footprint.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "sim_test_support.hpp"

namespace littermap::sim {
namespace {

using test::MakePrimitive;
constexpr double kPi = std::numbers::pi;

TEST(Footprint, StandingAndLyingObjectsCoverTheirHorizontalExtent) {
  // A bottle 7 cm across and 25 cm long.
  WorldObject bottle = MakePrimitive(Shape::kCylinder, {3, 4, 0.1}, {0.07, 0.07, 0.25}, 0.3);
  Footprint standing = FootprintOf(bottle);
  EXPECT_EQ(standing.center_m, Eigen::Vector2d(3, 4));
  EXPECT_NEAR(standing.size_m.x(), 0.07, 1e-12);
  EXPECT_NEAR(standing.size_m.y(), 0.07, 1e-12);
  EXPECT_DOUBLE_EQ(standing.yaw_rad, 0.3);
  bottle.orientation.pitch_rad = kPi / 2;  // lying: its length points along the heading
  const Footprint lying = FootprintOf(bottle);
  EXPECT_NEAR(lying.size_m.x(), 0.25, 1e-12);
  EXPECT_NEAR(lying.size_m.y(), 0.07, 1e-12);
}

TEST(Footprint, OverlapFollowsTheHeadingAndTheGap) {
  // Two bottles lying side by side, 10 cm between their axes, 3 cm between their sides.
  Footprint a{{10, 20}, {0.25, 0.07}, 0}, b{{10, 20.10}, {0.25, 0.07}, 0};
  EXPECT_FALSE(FootprintsOverlap(a, b, 0.02));
  EXPECT_TRUE(FootprintsOverlap(a, b, 0.04));
  // Turned across each other, they cross.
  b.yaw_rad = kPi / 2;
  EXPECT_TRUE(FootprintsOverlap(a, b, 0.02));
  // Two bottles on a diagonal heading, centres 0.21 m apart: end to end they reach each
  // other, side by side they are 0.14 m apart though their circumscribed circles meet.
  Footprint c{{0, 0}, {0.25, 0.07}, kPi / 4}, d{{0.15, 0.15}, {0.25, 0.07}, kPi / 4};
  EXPECT_TRUE(FootprintsOverlap(c, d, 0.0));
  d.center_m = {0.15, -0.15};
  EXPECT_FALSE(FootprintsOverlap(c, d, 0.02));
  // One inside the other (a bottle through a bottle) overlaps whatever the gap.
  EXPECT_TRUE(FootprintsOverlap(a, Footprint{{10.01, 20}, {0.07, 0.07}, 0}, 0));
}

}  // namespace
}  // namespace littermap::sim
