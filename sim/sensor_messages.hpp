#pragma once
// The ROS messages of the simulated robot's own sensors, filled the way their drivers fill them:
// the IMU's orientation with covariance, the camera driver's CameraInfo and the static
// extrinsics of the simulated mounts. (Scans and odometry: bag/sensor_messages.hpp.)

#include "bag/ros_messages.hpp"
#include "core/time.hpp"
#include "sim/camera_model.hpp"
#include "sim/route.hpp"
#include "sim/simulation.hpp"

namespace littermap::sim {

// base_link -> laser and base_link -> camera_color_optical_frame.
msg::TFMessage StaticTransformsMessage(TimestampNs stamp_ns, const Simulation& simulation);

msg::Imu ImuMessage(TimestampNs stamp_ns, const ImuSample& sample, double tilt_sigma_rad);

// Distortion-free ("plumb_bob" with D = 0) CameraInfo: K, R = I, P = [K | 0].
msg::CameraInfo CameraInfoMessage(const PinholeCamera& camera, const msg::Header& header);

}  // namespace littermap::sim
