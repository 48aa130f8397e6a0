#pragma once
// The ROS messages of a run, built from sensor values (the simulator's or real sensors') the way
// the ROS drivers fill them: urg_node's LaserScan, a wheel-odometry Odometry and the static
// extrinsics. (The simulated IMU and camera have theirs in sim/sensor_messages.hpp.)

#include <string>

#include <Eigen/Geometry>

#include "bag/ros_messages.hpp"
#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "core/time.hpp"

namespace littermap::bag::sensor_messages {

// base_link -> child, stamped stamp_ns.
msg::TransformStamped TransformFromBase(TimestampNs stamp_ns, const std::string& child,
                                        const Eigen::Isometry3d& T_base_child);
// /tf_static of a run: base_link -> laser and base_link -> camera_color_optical_frame.
msg::TFMessage StaticTransforms(TimestampNs stamp_ns, const Eigen::Isometry3d& T_base_laser,
                                const Eigen::Isometry3d& T_base_optical);

// Wheel odometry: the pose in odom, the forward and turn rates in base_link.
msg::Odometry Odometry(TimestampNs stamp_ns, const PlanarPose& T_odom_base, double linear_mps,
                       double angular_radps);
msg::LaserScan Scan(TimestampNs stamp_ns, const LaserScan& scan);

}  // namespace littermap::bag::sensor_messages
