#include "reconstruct/scan_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_set>

#include "core/error.hpp"

namespace littermap::reconstruct {

void ScanPointsOptions::Validate() const {
  if (!(min_range_m >= 0) || !(max_range_m > min_range_m)) {
    throw UsageError("scan points: need 0 <= min_range_m < max_range_m, got " +
                     std::to_string(min_range_m) + ", " + std::to_string(max_range_m));
  }
  if (!(laser_height_m >= 0) || !(ground_range_fraction > 0 && ground_range_fraction <= 1)) {
    throw UsageError("scan points: need laser_height_m >= 0 and ground_range_fraction in (0, 1]");
  }
}

ScanPoints ScanToPoints(const LaserScan& scan, const PlanarPose& T_base_laser,
                        const ScanPointsOptions& options, const std::optional<Tilt>& tilt) {
  const bool ground_filter = tilt && options.laser_height_m > 0;
  // A beam at heading h in base_link, (cos h, sin h, 0), after the tilt R = Ry(pitch) Rx(roll):
  //   x = cos(pitch) cos h + sin(pitch) sin(roll) sin h
  //   y = cos(roll) sin h
  //   z = -sin(pitch) cos h + cos(pitch) sin(roll) sin h
  // Its echo off an upright trunk or wall lies at r (x, y) in the ground plane, not r (cos h,
  // sin h): 14 degrees of pitch on a root put a trunk 5 m ahead 15 cm too far.
  const double pitch = tilt ? tilt->pitch_rad : 0, roll = tilt ? tilt->roll_rad : 0;
  const double x_cos = std::cos(pitch), x_sin = std::sin(pitch) * std::sin(roll);
  const double y_sin = std::cos(roll);
  const double down_x = -std::sin(pitch), down_y = std::cos(pitch) * std::sin(roll);
  const Eigen::Vector2d laser_base(T_base_laser.x_m, T_base_laser.y_m);
  ScanPoints result;
  result.beams = scan.ranges_m.size();
  result.points_base.reserve(scan.ranges_m.size());
  const double max_range = std::min(options.max_range_m, scan.range_max_m);
  const double min_range = std::max(options.min_range_m, scan.range_min_m);
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double r = scan.ranges_m[i];
    // "r < max_range" rejects NaN too; a reading at range_max means no echo (REP 117, CARMEN).
    if (!(r >= min_range && r < max_range)) continue;
    const double angle = scan.AngleOf(i);
    if (!tilt) {
      result.points_base.push_back(
          Transform(T_base_laser, Eigen::Vector2d(r * std::cos(angle), r * std::sin(angle))));
      ++result.valid_beams;
      continue;
    }
    const double heading = angle + T_base_laser.theta_rad;
    const double c = std::cos(heading), s = std::sin(heading);
    if (ground_filter) {
      const double vertical = down_x * c + down_y * s;
      if (vertical < 0 && r >= options.ground_range_fraction * options.laser_height_m / -vertical) {
        ++result.ground_beams;
        continue;
      }
    }
    result.points_base.push_back(laser_base +
                                 r * Eigen::Vector2d(x_cos * c + x_sin * s, y_sin * s));
    ++result.valid_beams;
  }
  return result;
}

std::vector<std::size_t> VoxelIndices(const Points2& points, double voxel_size_m) {
  std::vector<std::size_t> kept;
  kept.reserve(points.size());
  if (voxel_size_m <= 0) {
    for (std::size_t i = 0; i < points.size(); ++i) kept.push_back(i);
    return kept;
  }
  std::unordered_set<std::uint64_t> occupied;
  occupied.reserve(points.size() * 2);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto ix = static_cast<std::int64_t>(std::floor(points[i].x() / voxel_size_m));
    const auto iy = static_cast<std::int64_t>(std::floor(points[i].y() / voxel_size_m));
    const std::uint64_t key =
        (static_cast<std::uint64_t>(ix) << 32) ^ (static_cast<std::uint64_t>(iy) & 0xffffffffULL);
    if (occupied.insert(key).second) kept.push_back(i);
  }
  return kept;
}

Points2 VoxelDownsample(const Points2& points, double voxel_size_m) {
  Points2 kept;
  for (std::size_t i : VoxelIndices(points, voxel_size_m)) kept.push_back(points[i]);
  return kept;
}

Points2 TransformPoints(const PlanarPose& T, const Points2& points) {
  Points2 out;
  out.reserve(points.size());
  for (const Eigen::Vector2d& p : points) out.push_back(Transform(T, p));
  return out;
}

double TiltAngle(const Tilt& tilt) {
  return std::acos(std::clamp(std::cos(tilt.roll_rad) * std::cos(tilt.pitch_rad), -1.0, 1.0));
}

}  // namespace littermap::reconstruct
