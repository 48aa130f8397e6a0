#pragma once
// A synthetic polygonal room and a noiseless ray-cast laser for tests with known answers.

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Core>

#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::test {

struct Segment {
  Eigen::Vector2d a, b;
};

// A 12 m x 7 m room with a pillar, an alcove and a slanted cabinet: enough structure that the
// pose is constrained in every direction.
inline std::vector<Segment> Room() {
  std::vector<Segment> walls;
  const std::vector<Eigen::Vector2d> outline = {{0, 0},  {12, 0}, {12, 3}, {13, 3},
                                                {13, 5}, {12, 5}, {12, 7}, {0, 7}};
  for (std::size_t i = 0; i < outline.size(); ++i) {
    walls.push_back({outline[i], outline[(i + 1) % outline.size()]});
  }
  const std::vector<Eigen::Vector2d> pillar = {{5, 3}, {6, 3}, {6, 3.6}, {5, 3.6}};
  for (std::size_t i = 0; i < pillar.size(); ++i) {
    walls.push_back({pillar[i], pillar[(i + 1) % pillar.size()]});
  }
  walls.push_back({{1, 5.5}, {2.5, 6.5}});
  return walls;
}

// Range along a ray from origin in direction angle, or +inf.
inline double CastRay(const std::vector<Segment>& walls, const Eigen::Vector2d& origin,
                      double angle) {
  const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& wall : walls) {
    const Eigen::Vector2d e = wall.b - wall.a;
    const double denominator = d.x() * e.y() - d.y() * e.x();
    if (std::abs(denominator) < 1e-12) continue;
    const Eigen::Vector2d w = wall.a - origin;
    const double t = (w.x() * e.y() - w.y() * e.x()) / denominator;
    const double u = (w.x() * d.y() - w.y() * d.x()) / denominator;
    if (t > 0 && u >= 0 && u <= 1) best = std::min(best, t);
  }
  return best;
}

// A 360-beam, 360-degree scan from the pose (laser at base_link), ranges beyond 30 m as 30.
inline LaserScan ScanFrom(const std::vector<Segment>& walls, const PlanarPose& pose,
                          int beams = 360) {
  LaserScan scan;
  scan.angle_min_rad = -std::numbers::pi;
  scan.angle_increment_rad = 2 * std::numbers::pi / beams;
  scan.range_min_m = 0.05;
  scan.range_max_m = 30;
  for (int i = 0; i < beams; ++i) {
    const double r = CastRay(walls, {pose.x_m, pose.y_m}, pose.theta_rad + scan.AngleOf(i));
    scan.ranges_m.push_back(static_cast<float>(std::min(r, 30.0)));
  }
  return scan;
}

// The room seen from `pose`: scan points in the base frame, one per 5 cm voxel.
inline reconstruct::Points2 RoomPoints(const PlanarPose& pose) {
  return reconstruct::VoxelDownsample(
      reconstruct::ScanToPoints(ScanFrom(Room(), pose), {}, {}).points_base, 0.05);
}

}  // namespace littermap::test
