#pragma once
// The ROS messages of a run, built from sensor values (the simulator's or real sensors') the way
// the ROS drivers fill them: urg_node's LaserScan, a wheel-odometry Odometry, an IMU's
// orientation with covariance, the camera driver's CameraInfo, and the static extrinsics.

#include <string>

#include <Eigen/Geometry>

#include "capture/ros_messages.hpp"
#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "core/time.hpp"
#include "sim/camera_model.hpp"
#include "sim/route.hpp"
#include "sim/simulation.hpp"

namespace littermap::sensor_messages {

// base_link -> child, stamped stamp_ns.
msg::TransformStamped TransformFromBase(TimestampNs stamp_ns, const std::string& child,
                                        const Eigen::Isometry3d& T_base_child);
// The simulated robot's base_link -> laser and base_link -> camera_color_optical_frame.
msg::TFMessage StaticTransforms(TimestampNs stamp_ns, const sim::Simulation& simulation);

// Wheel odometry: the pose in odom, the forward and turn rates in base_link.
msg::Odometry Odometry(TimestampNs stamp_ns, const PlanarPose& T_odom_base, double linear_mps,
                       double angular_radps);
msg::LaserScan Scan(TimestampNs stamp_ns, const LaserScan& scan);
msg::Imu Imu(TimestampNs stamp_ns, const sim::ImuSample& sample, double tilt_sigma_rad);

// Distortion-free ("plumb_bob" with D = 0) CameraInfo: K, R = I, P = [K | 0].
msg::CameraInfo CameraInfo(const sim::PinholeCamera& camera, const msg::Header& header);

}  // namespace littermap::sensor_messages
