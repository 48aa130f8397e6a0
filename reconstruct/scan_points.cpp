#include "reconstruct/scan_points.hpp"

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
  // Vertical component of a horizontal beam at heading a in base_link after the tilt
  // R = Ry(pitch) Rx(roll): -sin(pitch) cos(a) + cos(pitch) sin(roll) sin(a).
  const double down_x = ground_filter ? -std::sin(tilt->pitch_rad) : 0;
  const double down_y = ground_filter ? std::cos(tilt->pitch_rad) * std::sin(tilt->roll_rad) : 0;
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
    if (ground_filter) {
      const double heading = angle + T_base_laser.theta_rad;
      const double vertical = down_x * std::cos(heading) + down_y * std::sin(heading);
      if (vertical < 0 && r >= options.ground_range_fraction * options.laser_height_m / -vertical) {
        ++result.ground_beams;
        continue;
      }
    }
    result.points_base.push_back(
        Transform(T_base_laser, Eigen::Vector2d(r * std::cos(angle), r * std::sin(angle))));
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

}  // namespace littermap::reconstruct
