#include "sim/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "sim/camera_model.hpp"
#include "sim/odometry_model.hpp"
#include "sim/random.hpp"

namespace littermap::sim {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180;
constexpr double kGravityMps2 = 9.81;

// Exposure times of the camera frames: offset + k / rate + jitter clipped to ±3σ (CameraSpec).
std::vector<double> CameraTimes(const CameraSpec& camera, double duration_s, std::uint64_t seed) {
  std::vector<double> times;
  const double offset_s = camera.clock_offset_ms / 1000, sigma_s = camera.jitter_sigma_ms / 1000;
  for (std::size_t k = 0;; ++k) {
    const double nominal = offset_s + static_cast<double>(k) / camera.rate_hz;
    if (nominal > duration_s + 1e-9) break;
    Rng rng(seed, 3'000'000 + k);
    const double jitter = sigma_s * std::clamp(rng.Normal(), -3.0, 3.0);
    times.push_back(std::clamp(nominal + jitter, 0.0, duration_s));
  }
  return times;
}

}  // namespace

Simulation::Simulation(const WorldSpec& spec, const SimulationOptions& options)
    : world_(std::make_unique<World>(GenerateWorld(spec))),
      T_base_laser_(MountPose(spec.robot.laser.mount)),
      T_base_camera_(MountPose(spec.robot.camera.mount)),
      scan_rate_hz_(spec.robot.laser.rate_hz) {
  if (world_->route_m.size() < 2) {
    throw BadInputError(spec.source.string() + ": route: needs at least two waypoints");
  }
  DriveOptions drive;
  drive.speed_mps = spec.DrivenRoute().speed_mps;
  drive.max_angular_speed_radps = spec.robot.max_angular_speed_radps;
  drive.rate_hz = spec.robot.odometry.rate_hz;
  drive.max_duration_s = options.max_duration_s;
  drive.dock = spec.DrivenRoute().come_home;
  drive_ = DriveRoute(world_->route_m, drive);
  std::vector<PlanarPose> truth;
  truth.reserve(drive_.states.size());
  for (const RobotState& state : drive_.states) truth.push_back(state.pose);
  odometry_ = SimulateOdometry(truth, spec.robot.odometry, spec.RunSeed(), spec.bumps);
  LaserSimulatorOptions laser;
  laser.model = LaserPreset(spec.robot.laser.preset);
  laser.range_noise_sigma_m = spec.robot.laser.range_noise_sigma_m;
  laser.mixed_pixel_probability = spec.robot.laser.mixed_pixel_probability;
  laser.dropout_probability = spec.robot.laser.dropout_probability;
  laser_ = std::make_unique<LaserSimulator>(*world_, laser);
  camera_times_s_ = CameraTimes(spec.robot.camera, duration_s(), spec.RunSeed());
}

Eigen::Isometry3d Simulation::T_base_optical() const { return T_base_camera_ * T_body_optical(); }

Eigen::Isometry3d Simulation::TrueOpticalPose(double t_s) const {
  return TrueBasePose(t_s) * T_base_optical();
}

Eigen::Isometry3d Simulation::TrueBasePose(double t_s, RollPitchYaw* rpy) const {
  return BasePose3(InterpolatePose(drive_.states, t_s), world_->terrain, world_->spec.bumps, rpy);
}

std::size_t Simulation::scan_count() const {
  return static_cast<std::size_t>(std::floor(duration_s() * scan_rate_hz_ + 1e-9)) + 1;
}

LaserScan Simulation::Scan(std::size_t k) const {
  const double t = ScanTime(k);
  LaserScan scan =
      laser_->Scan(TrueBasePose(t) * T_base_laser_, FromSeconds(t), world_->spec.RunSeed(), k);
  scan.scan_time_s = 1.0 / scan_rate_hz_;
  return scan;
}

std::size_t Simulation::imu_count() const {
  return static_cast<std::size_t>(
             std::floor(duration_s() * world_->spec.robot.imu.rate_hz + 1e-9)) +
         1;
}

ImuSample Simulation::Imu(std::size_t k) const {
  const ImuSpec& spec = world_->spec.robot.imu;
  ImuSample sample;
  sample.t_s = static_cast<double>(k) / spec.rate_hz;
  RollPitchYaw rpy;
  const Eigen::Isometry3d T_world_base = TrueBasePose(sample.t_s, &rpy);
  Rng rng(world_->spec.RunSeed(), 2'000'000 + k);
  const double sigma = spec.tilt_noise_deg * kDegToRad;
  // Heading from the wheel odometry: an IMU without magnetometer knows no absolute yaw.
  const double odom_t = sample.t_s * world_->spec.robot.odometry.rate_hz;
  const std::size_t i =
      std::min(static_cast<std::size_t>(std::llround(odom_t)), odometry_.size() - 1);
  sample.orientation = Eigen::Quaterniond(
      RotationFromRpy({rpy.roll_rad + sigma * rng.Normal(), rpy.pitch_rad + sigma * rng.Normal(),
                       odometry_[i].theta_rad}));
  // The drive state at the sample's time holds the turn rate of the step that ended there. The
  // time in steps is k / imu_rate * odometry_rate: in floating point it can come out a hair
  // below a whole step, and the step before's rate then stood in for a sample at a turn's
  // start or end (a whole step at 1 rad/s: 1.1 degrees that the gyro never turned).
  const std::size_t j =
      std::min(static_cast<std::size_t>(std::floor(odom_t + 1e-6)), drive_.states.size() - 1);
  sample.angular_velocity_radps = {0.01 * rng.Normal(), 0.01 * rng.Normal(),
                                   drive_.states[j].angular_radps + 0.01 * rng.Normal()};
  sample.linear_acceleration_mps2 =
      T_world_base.linear().transpose() * Eigen::Vector3d(0, 0, kGravityMps2);
  return sample;
}

}  // namespace littermap::sim
