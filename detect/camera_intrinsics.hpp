#pragma once
// Pinhole intrinsics of a registered RGB-D camera (depth in the colour camera's optical frame:
// z forward, x right, y down), read from a sensor_msgs/CameraInfo.

#include <string>

#include <Eigen/Core>

#include "bag/ros_messages.hpp"

namespace littermap::detect {

struct CameraIntrinsics {
  double fx = 525, fy = 525;
  double cx = 319.5, cy = 239.5;
  int width = 640, height = 480;

  Eigen::Vector3f BackProject(int u, int v, float z_m) const {
    return {static_cast<float>((u - cx) / fx) * z_m, static_cast<float>((v - cy) / fy) * z_m, z_m};
  }
  Eigen::Vector2d Project(const Eigen::Vector3d& p_camera) const {
    return {fx * p_camera.x() / p_camera.z() + cx, fy * p_camera.y() / p_camera.z() + cy};
  }
};

// K of the CameraInfo (distortion is ignored: registered Kinect-class images are close to
// distortion-free at VGA). Throws BadInputError naming `source` for a zero focal length or size.
CameraIntrinsics IntrinsicsFromCameraInfo(const msg::CameraInfo& info, const std::string& source);

}  // namespace littermap::detect
