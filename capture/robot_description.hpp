#pragma once
// Where the sensors sit on the robot, from a small YAML file, for /tf_static of a captured run:
//
//   laser:
//     mount: {x_m: 0.15, y_m: 0, z_m: 0.30, roll_deg: 0, pitch_deg: 0, yaw_deg: 0}
//   camera:   # the camera body, x forward (the optical frame, z forward, is derived)
//     mount: {x_m: 0.20, y_m: 0, z_m: 0.50, roll_deg: 0, pitch_deg: 25, yaw_deg: 0}
//
// Mounts are poses on base_link (x forward, y left, z up; roll, pitch, yaw as in REP 103), the
// same form as a simulated world's robot section, so a simulated and a real run read alike.

#include <filesystem>

#include <Eigen/Geometry>

#include "bag/ros_messages.hpp"
#include "core/time.hpp"

namespace littermap::capture {

struct RobotDescription {
  Eigen::Isometry3d T_base_laser = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_base_optical = Eigen::Isometry3d::Identity();  // camera optical frame
};

// Throws BadInputError naming the file and key for an unreadable file, an unknown key or a
// value that is not a number; a missing sensor or key is 0.
RobotDescription ReadRobotDescription(const std::filesystem::path& path);

// base_link -> laser and base_link -> camera_color_optical_frame.
msg::TFMessage StaticTransforms(TimestampNs stamp_ns, const RobotDescription& robot);

}  // namespace littermap::capture
