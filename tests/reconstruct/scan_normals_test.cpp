// Line normals along a scan: a far wall's sparse echoes keep their line, normals face the sensor,
// a depth jump ends a line, and the sparse echoes of a wall at a grazing angle are not matchable.

#include "reconstruct/scan_normals.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "synthetic_world.hpp"

namespace littermap::reconstruct {
namespace {

// A 1-degree scan from the origin of the given walls, in beam order.
Points2 ScanOf(const std::vector<test::Segment>& walls) {
  return ScanToPoints(test::ScanFrom(walls, {}, 360), {}, {}).points_base;
}

TEST(ScanNormals, AFarWallKeepsItsLineAndFacesTheSensor) {
  // A wall 20 m ahead: its echoes are 35 cm apart, beyond any fixed 0.5 m neighbourhood of five.
  const Points2 points = ScanOf({{{20, -3}, {20, 3}}});
  ASSERT_GE(points.size(), 15u);
  const ScanNormals normals = EstimateScanNormals(points, {});
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(normals.normals[i].x(), -1, 1e-3) << i;  // towards the sensor
    EXPECT_NEAR(normals.normals[i].y(), 0, 0.05) << i;
    EXPECT_TRUE(normals.matchable[i]);
  }
}

TEST(ScanNormals, ADepthJumpEndsALine) {
  // A near wall in front of a far one, side by side in the scan: the two ends next to the jump
  // take no neighbour across it, so their normals are those of their own walls.
  const Points2 points = ScanOf({{{3, -2}, {3, 0}}, {{8, 0.05}, {8, 3}}});
  const ScanNormals normals = EstimateScanNormals(points, {});
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_GT(normals.normals[i].squaredNorm(), 0.5) << i;
    EXPECT_NEAR(normals.normals[i].x(), -1, 1e-3) << "point " << i << " at x " << points[i].x();
  }
}

TEST(ScanNormals, TheSparseEchoesOfAGrazedWallAreNotMatchable) {
  // A corridor wall 1 m to the side: beyond a few metres its echoes lie metres apart.
  const Points2 points = ScanOf({{{0.5, 1}, {60, 1}}});
  const ScanNormals normals = EstimateScanNormals(points, {});
  std::size_t near_lines = 0, far_unmatchable = 0, far = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].x() < 3) near_lines += normals.normals[i].squaredNorm() > 0.5;
    if (points[i].x() > 10) {
      ++far;
      far_unmatchable += !normals.matchable[i];
    }
  }
  EXPECT_GE(near_lines, 20u);
  ASSERT_GE(far, 2u);
  EXPECT_EQ(far_unmatchable, far);
}

TEST(ScanNormals, APostIsMatchablePointToPoint) {
  // Three echoes of a 6 cm post: no line, but finely sampled.
  const Points2 points = {{2, -0.03}, {1.97, 0}, {2, 0.03}};
  const ScanNormals normals = EstimateScanNormals(points, {});
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(normals.normals[i].squaredNorm(), 0) << i;
    EXPECT_TRUE(normals.matchable[i]) << i;
  }
  const ScanNormals alone = EstimateScanNormals({{5, 0}}, {});
  EXPECT_FALSE(alone.matchable[0]);
}

TEST(ScanNormals, BadOptionsAreRefused) {
  ScanNormalsOptions options;
  options.neighbours_per_side = 0;
  EXPECT_THROW(EstimateScanNormals({}, options), UsageError);
  options = {};
  options.min_gap_m = 0;
  EXPECT_THROW(EstimateScanNormals({}, options), UsageError);
}

}  // namespace
}  // namespace littermap::reconstruct
