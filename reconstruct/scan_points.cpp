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
}

ScanPoints ScanToPoints(const LaserScan& scan, const PlanarPose& T_base_laser,
                        const ScanPointsOptions& options) {
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
