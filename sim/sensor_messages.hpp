#pragma once
// The ROS messages of the simulated robot's own sensors, filled the way their drivers fill them:
// the IMU's orientation with covariance and the camera driver's CameraInfo. (Scans, odometry
// and the static extrinsics: bag/sensor_messages.hpp.)

#include "bag/ros_messages.hpp"
#include "core/time.hpp"
#include "sim/camera_model.hpp"
#include "sim/simulation.hpp"

namespace littermap::sim {

msg::Imu ImuMessage(TimestampNs stamp_ns, const ImuSample& sample, double tilt_sigma_rad);

// Distortion-free ("plumb_bob" with D = 0) CameraInfo: K, R = I, P = [K | 0].
msg::CameraInfo CameraInfoMessage(const PinholeCamera& camera, const msg::Header& header);

}  // namespace littermap::sim
