#pragma once
// Helpers for 3D poses (Eigen::Isometry3d). Euler angles follow ROS (REP 103): roll about x,
// pitch about y, yaw about z, applied as R = Rz(yaw) * Ry(pitch) * Rx(roll). With x forward and
// z up, a positive pitch tips the nose down and a positive roll lifts the left side.

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/planar_pose.hpp"

namespace littermap {

struct RollPitchYaw {
  double roll_rad = 0;
  double pitch_rad = 0;
  double yaw_rad = 0;
};

inline Eigen::Matrix3d RotationFromRpy(const RollPitchYaw& rpy) {
  return (Eigen::AngleAxisd(rpy.yaw_rad, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.pitch_rad, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.roll_rad, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// Inverse of RotationFromRpy, pitch in [-pi/2, pi/2].
inline RollPitchYaw RpyFromRotation(const Eigen::Matrix3d& R) {
  RollPitchYaw rpy;
  rpy.pitch_rad = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  rpy.roll_rad = std::atan2(R(2, 1), R(2, 2));
  rpy.yaw_rad = std::atan2(R(1, 0), R(0, 0));
  return rpy;
}

inline Eigen::Isometry3d MakeIsometry(const Eigen::Vector3d& translation_m,
                                      const RollPitchYaw& rpy) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = RotationFromRpy(rpy);
  T.translation() = translation_m;
  return T;
}

// The yaw of a rotation (ZYX order, as RpyFromRotation): the heading of its x axis.
inline double YawOf(const Eigen::Quaterniond& q) {
  return std::atan2(2 * (q.w() * q.z() + q.x() * q.y()), 1 - 2 * (q.y() * q.y() + q.z() * q.z()));
}

// The planar part of a 3D pose: x, y and the heading of its x axis projected on the plane.
inline PlanarPose ToPlanar(const Eigen::Isometry3d& T) {
  const Eigen::Vector3d x_axis = T.linear().col(0);
  return {T.translation().x(), T.translation().y(), std::atan2(x_axis.y(), x_axis.x())};
}

}  // namespace littermap
