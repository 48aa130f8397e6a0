#include "capture/sim_recorder.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

#include "capture/output_guard.hpp"
#include "capture/topics.hpp"
#include "sim/ground_truth.hpp"
#include "sim/simulation.hpp"

namespace littermap {
namespace {

msg::Header MakeHeader(TimestampNs stamp_ns, const char* frame_id) {
  msg::Header header;
  header.stamp.sec = static_cast<std::int32_t>(stamp_ns / kNanosecondsPerSecond);
  header.stamp.nanosec = static_cast<std::uint32_t>(stamp_ns % kNanosecondsPerSecond);
  header.frame_id = frame_id;
  return header;
}

msg::Quaternion ToMsg(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }

msg::TransformStamped Transform(TimestampNs stamp_ns, const char* child,
                                const Eigen::Isometry3d& T_base_child) {
  msg::TransformStamped transform;
  transform.header = MakeHeader(stamp_ns, frames::kBase);
  transform.child_frame_id = child;
  const Eigen::Vector3d t = T_base_child.translation();
  transform.transform.translation = {t.x(), t.y(), t.z()};
  transform.transform.rotation = ToMsg(Eigen::Quaterniond(T_base_child.linear()));
  return transform;
}

// The optical frame (z forward, x right, y down) in the camera body frame (x forward, z up).
Eigen::Isometry3d BodyToOptical() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  return T;
}

msg::Odometry MakeOdometry(TimestampNs stamp_ns, const PlanarPose& T_odom_base,
                           const sim::RobotState& state) {
  msg::Odometry odometry;
  odometry.header = MakeHeader(stamp_ns, frames::kOdom);
  odometry.child_frame_id = frames::kBase;
  odometry.pose.pose.position = {T_odom_base.x_m, T_odom_base.y_m, 0};
  odometry.pose.pose.orientation = {0, 0, std::sin(T_odom_base.theta_rad / 2),
                                    std::cos(T_odom_base.theta_rad / 2)};
  odometry.twist.twist.linear.x = state.linear_mps;
  odometry.twist.twist.angular.z = state.angular_radps;
  return odometry;
}

msg::LaserScan MakeScan(TimestampNs stamp_ns, const LaserScan& scan) {
  msg::LaserScan out;
  out.header = MakeHeader(stamp_ns, frames::kLaser);
  out.angle_min = static_cast<float>(scan.angle_min_rad);
  out.angle_max = static_cast<float>(scan.angle_max_rad());
  out.angle_increment = static_cast<float>(scan.angle_increment_rad);
  // A rotating mirror: one revolution per scan period.
  out.time_increment =
      static_cast<float>(scan.scan_time_s * scan.angle_increment_rad / (2 * std::numbers::pi));
  out.scan_time = static_cast<float>(scan.scan_time_s);
  out.range_min = static_cast<float>(scan.range_min_m);
  out.range_max = static_cast<float>(scan.range_max_m);
  out.ranges = scan.ranges_m;
  return out;
}

msg::Imu MakeImu(TimestampNs stamp_ns, const sim::ImuSample& sample, double tilt_sigma_rad) {
  msg::Imu imu;
  imu.header = MakeHeader(stamp_ns, frames::kBase);
  imu.orientation = ToMsg(sample.orientation);
  const double var = tilt_sigma_rad * tilt_sigma_rad;
  imu.orientation_covariance = {var, 0, 0, 0, var, 0, 0, 0, 1e6};  // yaw: unknown
  const Eigen::Vector3d& w = sample.angular_velocity_radps;
  const Eigen::Vector3d& a = sample.linear_acceleration_mps2;
  imu.angular_velocity = {w.x(), w.y(), w.z()};
  imu.angular_velocity_covariance = {1e-4, 0, 0, 0, 1e-4, 0, 0, 0, 1e-4};
  imu.linear_acceleration = {a.x(), a.y(), a.z()};
  return imu;
}

}  // namespace

SimRecordResult RecordSimulation(const sim::WorldSpec& world_spec,
                                 const std::filesystem::path& bag_path,
                                 const std::filesystem::path& truth_dir,
                                 const SimRecordOptions& options,
                                 const ProgressCallback& progress) {
  sim::WorldSpec spec = world_spec;
  if (options.seed) spec.seed = *options.seed;
  const sim::Simulation simulation(spec, {options.max_duration_s});
  OutputGuard guard;
  guard.Add(bag_path);
  guard.Add(truth_dir);
  const TimestampNs start_ns = FromSeconds(spec.start_time_s);
  BagWriter writer(bag_path, options.bag);
  writer.AddTopic<msg::TFMessage>(topics::kTfStatic, TopicQos::kLatched);
  writer.AddTopic<msg::Odometry>(topics::kOdometry, TopicQos::kReliable);
  writer.AddTopic<msg::Imu>(topics::kImu, TopicQos::kSensorData);
  writer.AddTopic<msg::LaserScan>(topics::kScan, TopicQos::kSensorData);
  writer.WriteMessage(
      topics::kTfStatic, start_ns,
      msg::TFMessage{
          {Transform(start_ns, frames::kLaser, simulation.T_base_laser()),
           Transform(start_ns, frames::kCamera, simulation.T_base_camera() * BodyToOptical())}});

  SimRecordResult result;
  const auto& states = simulation.states();
  const double odom_rate_hz = spec.robot.odometry.rate_hz;
  const double tilt_sigma_rad = spec.robot.imu.tilt_noise_deg * std::numbers::pi / 180;
  const std::size_t scans = simulation.scan_count(), imus = simulation.imu_count();
  std::size_t scan = 0, imu = 0;
  const auto clock_start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < states.size(); ++i) {
    const double t = static_cast<double>(i) / odom_rate_hz;
    // Odometry first: a consumer that sees a scan has the odometry of its time already.
    writer.WriteMessage(
        topics::kOdometry, start_ns + FromSeconds(t),
        MakeOdometry(start_ns + FromSeconds(t),
                     Between(simulation.odometry().front(), simulation.odometry()[i]), states[i]));
    for (; imu < imus && static_cast<double>(imu) / spec.robot.imu.rate_hz <= t + 1e-9; ++imu) {
      const sim::ImuSample sample = simulation.Imu(imu);
      const TimestampNs stamp = start_ns + FromSeconds(sample.t_s);
      writer.WriteMessage(topics::kImu, stamp, MakeImu(stamp, sample, tilt_sigma_rad));
    }
    for (; scan < scans && simulation.ScanTime(scan) <= t + 1e-9; ++scan) {
      const LaserScan laser = simulation.Scan(scan);
      const TimestampNs stamp = start_ns + laser.stamp_ns;
      writer.WriteMessage(topics::kScan, stamp, MakeScan(stamp, laser));
      if (scan % 50 == 0) ReportProgress(progress, {"simulating", scan, scans});
    }
  }
  result.simulate_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  writer.Close();
  ReportProgress(progress, {"simulating", scans, scans});
  const sim::GroundTruthResult truth =
      sim::WriteGroundTruth(truth_dir, simulation, spec.start_time_s);
  guard.Commit();

  const sim::World& world = simulation.world();
  result.scans = scan;
  result.odometry = states.size();
  result.imu = imu;
  result.duration_s = simulation.duration_s();
  result.distance_m = simulation.drive().distance_m;
  result.route_completed = simulation.drive().reached_goal;
  result.litter = truth.litter;
  result.natural = truth.natural;
  result.objects = world.objects.size();
  result.seed = spec.seed;
  result.laser = spec.robot.laser.preset;
  return result;
}

}  // namespace littermap
