#pragma once
// A stamped 3D pose T_world_body: what a trajectory is made of, read and written in the TUM
// format (bag/tum_trajectory.hpp) and graded by eval/trajectory_metrics.hpp.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/planar_pose.hpp"
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

}  // namespace littermap
