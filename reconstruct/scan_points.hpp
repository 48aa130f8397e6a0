#pragma once
// Laser ranges to 2D points in the robot (base_link) frame. Beams without a usable echo (NaN,
// +inf, at or beyond range_max, below range_min) are dropped, so a scan of only max-range or NaN
// readings yields no points and the tracker can count and skip it.

#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"

namespace littermap::reconstruct {

using Points2 = std::vector<Eigen::Vector2d>;

struct ScanPointsOptions {
  double min_range_m = 0.1;   // closer echoes are the robot itself
  double max_range_m = 40.0;  // longer echoes are sparse and noisy (outdoors)
  // Height of the laser above the ground; with the base's tilt it says where a tilted beam hits
  // the ground (0: unknown, no ground filtering).
  double laser_height_m = 0;
  // A beam is dropped from this fraction of its predicted ground range on (uneven ground).
  double ground_range_fraction = 0.8;
  void Validate() const;
};

// Roll and pitch of base_link against gravity (an IMU's orientation), ROS conventions.
struct Tilt {
  double roll_rad = 0;
  double pitch_rad = 0;
};

// The angle between the base's up axis and gravity's (rad).
double TiltAngle(const Tilt& tilt);

struct ScanPoints {
  Points2 points_base;  // T_base_laser applied
  std::size_t beams = 0;
  std::size_t valid_beams = 0;
  std::size_t ground_beams = 0;  // echoes dropped as ground hits
};

// With a tilt (and laser_height_m), echoes at or beyond where the beam meets the ground are
// dropped: on a bump the scanner sees the ground as an arc that moves with the robot, and ICP
// would lock onto it (thesis 2.5: "the laser hits the ground").
ScanPoints ScanToPoints(const LaserScan& scan, const PlanarPose& T_base_laser,
                        const ScanPointsOptions& options,
                        const std::optional<Tilt>& tilt = std::nullopt);

// One point per occupied square voxel (the first one seen), keeping the scan's order. Keeps
// dense near-range clusters from dominating ICP.
Points2 VoxelDownsample(const Points2& points, double voxel_size_m);
// The indices VoxelDownsample keeps, to carry per-point data (normals) along.
std::vector<std::size_t> VoxelIndices(const Points2& points, double voxel_size_m);

// T * p for a planar pose.
inline Eigen::Vector2d Transform(const PlanarPose& T, const Eigen::Vector2d& p) {
  const double c = std::cos(T.theta_rad), s = std::sin(T.theta_rad);
  return {T.x_m + c * p.x() - s * p.y(), T.y_m + s * p.x() + c * p.y()};
}

Points2 TransformPoints(const PlanarPose& T, const Points2& points);

}  // namespace littermap::reconstruct
