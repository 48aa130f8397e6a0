#pragma once
// One simulated survey run: the world, the robot's true motion along the route, its drifting
// wheel odometry, and on-demand laser scans and IMU samples at their own rates. Everything is a
// function of the WorldSpec (and its seed), so two runs with the same spec are identical.

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "core/laser_scan.hpp"
#include "core/planar_pose.hpp"
#include "core/pose3.hpp"
#include "sim/laser_simulator.hpp"
#include "sim/route.hpp"
#include "sim/world.hpp"

namespace littermap::sim {

struct SimulationOptions {
  double max_duration_s = std::numeric_limits<double>::infinity();  // truncates the route
};

struct ImuSample {
  double t_s = 0;
  Eigen::Quaterniond orientation;  // noisy roll/pitch, yaw from the odometry (no magnetometer)
  Eigen::Vector3d angular_velocity_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d linear_acceleration_mps2 = Eigen::Vector3d::Zero();  // gravity only
};

class Simulation {
 public:
  explicit Simulation(const WorldSpec& spec, const SimulationOptions& options = {});

  const World& world() const { return *world_; }
  const DriveResult& drive() const { return drive_; }
  // True base poses and odometry, one per drive state (odometry rate).
  const std::vector<RobotState>& states() const { return drive_.states; }
  const std::vector<PlanarPose>& odometry() const { return odometry_; }
  double duration_s() const { return drive_.states.back().t_s; }

  // The true 3D base pose at t_s (interpolated in the plane, then set on the terrain).
  Eigen::Isometry3d TrueBasePose(double t_s, RollPitchYaw* rpy = nullptr) const;

  std::size_t scan_count() const;
  double ScanTime(std::size_t k) const { return static_cast<double>(k) / scan_rate_hz_; }
  LaserScan Scan(std::size_t k) const;  // stamp relative to t = 0 (add the start time)

  std::size_t imu_count() const;
  ImuSample Imu(std::size_t k) const;

  // RGB-D frames: exposure times with the camera's clock offset and jitter (CameraSpec),
  // increasing, within [0, duration_s()].
  std::size_t camera_frame_count() const { return camera_times_s_.size(); }
  double CameraFrameTime(std::size_t k) const { return camera_times_s_[k]; }
  // The true pose of the camera's optical frame at t_s.
  Eigen::Isometry3d TrueOpticalPose(double t_s) const;

  const Eigen::Isometry3d& T_base_laser() const { return T_base_laser_; }
  const Eigen::Isometry3d& T_base_camera() const { return T_base_camera_; }  // camera body
  Eigen::Isometry3d T_base_optical() const;  // camera optical frame (z forward, y down)

 private:
  std::unique_ptr<World> world_;  // stable address: the laser simulator refers to it
  DriveResult drive_;
  std::vector<PlanarPose> odometry_;
  std::unique_ptr<LaserSimulator> laser_;
  Eigen::Isometry3d T_base_laser_;
  Eigen::Isometry3d T_base_camera_;
  double scan_rate_hz_ = 10;
  std::vector<double> camera_times_s_;
};

}  // namespace littermap::sim
