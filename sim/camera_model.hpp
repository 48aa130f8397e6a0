#pragma once
// Pinhole intrinsics of the simulated RGB-D camera in the optical frame (z forward, x right,
// y down; REP 103 "_optical" convention), without lens distortion: the Kinect's colour and depth
// images are delivered registered and close to distortion-free at this resolution.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/mount.hpp"

namespace littermap::sim {

struct PinholeCamera {
  // Kinect v1 colour camera at VGA (Smisek, Jancosek, Pajdla 2011: f ≈ 525 px).
  double fx = 525, fy = 525;
  double cx = 319.5, cy = 239.5;
  int width = 640, height = 480;

  // Pixel (u, v) of a point in the optical frame; only meaningful for p.z() > 0.
  Eigen::Vector2d Project(const Eigen::Vector3d& p_camera) const {
    return {fx * p_camera.x() / p_camera.z() + cx, fy * p_camera.y() / p_camera.z() + cy};
  }
  // The point at pixel (u, v) whose optical-axis depth is z_m.
  Eigen::Vector3d BackProject(double u, double v, double z_m) const {
    return {(u - cx) / fx * z_m, (v - cy) / fy * z_m, z_m};
  }
  // The unnormalised viewing ray of pixel (u, v), with z = 1.
  Eigen::Vector3d Ray(double u, double v) const { return {(u - cx) / fx, (v - cy) / fy, 1.0}; }
  bool Contains(double u, double v) const {
    return u >= -0.5 && v >= -0.5 && u < width - 0.5 && v < height - 0.5;
  }
};

}  // namespace littermap::sim
