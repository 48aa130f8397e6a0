#pragma once
// The ROS messages of a simulated run (capture/sim_recorder.hpp), built from the simulator's
// values the way the real drivers fill them: urg_node's LaserScan, a wheel-odometry Odometry, an
// IMU's orientation with covariance, the camera driver's CameraInfo, and the static extrinsics.

#include <Eigen/Geometry>

#include "capture/ros_messages.hpp"
#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "core/time.hpp"
#include "sim/camera_model.hpp"
#include "sim/route.hpp"
#include "sim/simulation.hpp"

namespace littermap::sim_messages {

// base_link -> laser and base_link -> camera_color_optical_frame, stamped stamp_ns.
msg::TFMessage StaticTransforms(TimestampNs stamp_ns, const sim::Simulation& simulation);

msg::Odometry Odometry(TimestampNs stamp_ns, const PlanarPose& T_odom_base,
                       const sim::RobotState& state);
msg::LaserScan Scan(TimestampNs stamp_ns, const LaserScan& scan);
msg::Imu Imu(TimestampNs stamp_ns, const sim::ImuSample& sample, double tilt_sigma_rad);

// Distortion-free ("plumb_bob" with D = 0) CameraInfo: K, R = I, P = [K | 0].
msg::CameraInfo CameraInfo(const sim::PinholeCamera& camera, const msg::Header& header);

}  // namespace littermap::sim_messages
