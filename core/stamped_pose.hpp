#pragma once
// A stamped 3D pose T_world_body: what a trajectory is made of, read and written in the TUM
// format (bag/tum_trajectory.hpp) and graded by eval/trajectory_metrics.hpp.

#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/planar_pose.hpp"
#include "core/pose3.hpp"
#include "core/time.hpp"

namespace littermap {

struct StampedPose {
  TimestampNs stamp_ns = 0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

// A planar pose as a 3D pose: z = 0, rotation about z by theta.
inline StampedPose StampedPoseFromPlanar(TimestampNs stamp_ns, const PlanarPose& pose) {
  StampedPose stamped;
  stamped.stamp_ns = stamp_ns;
  stamped.position_m = {pose.x_m, pose.y_m, 0.0};
  stamped.orientation =
      Eigen::Quaterniond(Eigen::AngleAxisd(pose.theta_rad, Eigen::Vector3d::UnitZ()));
  return stamped;
}

// A planar trajectory, (stamp, pose) pairs, as 3D poses.
inline std::vector<StampedPose> StampedPosesFromPlanar(
    const std::vector<std::pair<TimestampNs, PlanarPose>>& poses) {
  std::vector<StampedPose> stamped;
  stamped.reserve(poses.size());
  for (const auto& [stamp_ns, pose] : poses)
    stamped.push_back(StampedPoseFromPlanar(stamp_ns, pose));
  return stamped;
}

inline StampedPose StampedPoseFromIsometry(TimestampNs stamp_ns, const Eigen::Isometry3d& T) {
  return {stamp_ns, T.translation(), Eigen::Quaterniond(T.linear())};
}

// The pose's projection on the ground plane: x, y and the yaw of its orientation.
inline PlanarPose PlanarPoseOf(const StampedPose& pose) {
  return {pose.position_m.x(), pose.position_m.y(), YawOf(pose.orientation)};
}

}  // namespace littermap
