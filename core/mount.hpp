#pragma once
// Where a sensor sits on the robot: a pose on base_link (x forward, y left, z up; roll, pitch,
// yaw as in REP 103), the same in a simulated world's robot section and a real robot's
// description.

#include <Eigen/Geometry>

#include "core/yaml_fields.hpp"

namespace littermap {

struct MountSpec {  // a sensor's pose on base_link; rpy as in REP 103
  double x_m = 0, y_m = 0, z_m = 0;
  double roll_deg = 0, pitch_deg = 0, yaw_deg = 0;
};

// Reads x_m, y_m, z_m, roll_deg, pitch_deg, yaw_deg (each optional) of a mount mapping.
void ReadMount(YamlFields fields, MountSpec& mount);

Eigen::Isometry3d MountPose(const MountSpec& mount);

// T_body_optical: the optical frame (z forward, x right, y down) in the camera body frame
// (x forward, y left, z up), the rotation between a camera mount and its image (REP 103).
inline Eigen::Isometry3d T_body_optical() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  return T;
}

}  // namespace littermap
