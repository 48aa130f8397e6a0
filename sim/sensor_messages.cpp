#include "sim/sensor_messages.hpp"

#include "bag/message_header.hpp"
#include "bag/topics.hpp"

namespace littermap::sim {

msg::Imu ImuMessage(TimestampNs stamp_ns, const ImuSample& sample, double tilt_sigma_rad) {
  msg::Imu imu;
  imu.header = bag::MakeHeader(stamp_ns, frames::kBase);
  imu.orientation = bag::ToMsg(sample.orientation);
  const double var = tilt_sigma_rad * tilt_sigma_rad;
  imu.orientation_covariance = {var, 0, 0, 0, var, 0, 0, 0, 1e6};  // yaw: unknown
  const Eigen::Vector3d& w = sample.angular_velocity_radps;
  const Eigen::Vector3d& a = sample.linear_acceleration_mps2;
  imu.angular_velocity = {w.x(), w.y(), w.z()};
  imu.angular_velocity_covariance = {1e-4, 0, 0, 0, 1e-4, 0, 0, 0, 1e-4};
  imu.linear_acceleration = {a.x(), a.y(), a.z()};
  return imu;
}

msg::CameraInfo CameraInfoMessage(const PinholeCamera& camera, const msg::Header& header) {
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

}  // namespace littermap::sim
