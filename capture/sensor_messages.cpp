#include "capture/sensor_messages.hpp"

#include <cmath>
#include <numbers>

#include "capture/message_header.hpp"
#include "capture/topics.hpp"

namespace littermap::sensor_messages {
namespace {

msg::Quaternion ToMsg(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }

}  // namespace

msg::TransformStamped TransformFromBase(TimestampNs stamp_ns, const std::string& child,
                                        const Eigen::Isometry3d& T_base_child) {
  msg::TransformStamped transform;
  transform.header = MakeHeader(stamp_ns, frames::kBase);
  transform.child_frame_id = child;
  const Eigen::Vector3d t = T_base_child.translation();
  transform.transform.translation = {t.x(), t.y(), t.z()};
  transform.transform.rotation = ToMsg(Eigen::Quaterniond(T_base_child.linear()));
  return transform;
}

msg::TFMessage StaticTransforms(TimestampNs stamp_ns, const sim::Simulation& simulation) {
  return msg::TFMessage{
      {TransformFromBase(stamp_ns, frames::kLaser, simulation.T_base_laser()),
       TransformFromBase(stamp_ns, frames::kCamera, simulation.T_base_optical())}};
}

msg::Odometry Odometry(TimestampNs stamp_ns, const PlanarPose& T_odom_base, double linear_mps,
                       double angular_radps) {
  msg::Odometry odometry;
  odometry.header = MakeHeader(stamp_ns, frames::kOdom);
  odometry.child_frame_id = frames::kBase;
  odometry.pose.pose.position = {T_odom_base.x_m, T_odom_base.y_m, 0};
  odometry.pose.pose.orientation = {0, 0, std::sin(T_odom_base.theta_rad / 2),
                                    std::cos(T_odom_base.theta_rad / 2)};
  odometry.twist.twist.linear.x = linear_mps;
  odometry.twist.twist.angular.z = angular_radps;
  return odometry;
}

msg::LaserScan Scan(TimestampNs stamp_ns, const LaserScan& scan) {
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

msg::Imu Imu(TimestampNs stamp_ns, const sim::ImuSample& sample, double tilt_sigma_rad) {
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

msg::CameraInfo CameraInfo(const sim::PinholeCamera& camera, const msg::Header& header) {
  msg::CameraInfo info;
  info.header = header;
  info.width = static_cast<std::uint32_t>(camera.width);
  info.height = static_cast<std::uint32_t>(camera.height);
  info.distortion_model = "plumb_bob";
  info.d.assign(5, 0.0);
  info.k = {camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1};
  info.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.p = {camera.fx, 0, camera.cx, 0, 0, camera.fy, camera.cy, 0, 0, 0, 1, 0};
  return info;
}

}  // namespace littermap::sensor_messages
