#include "bag/sensor_messages.hpp"

#include <cmath>
#include <numbers>

#include "bag/message_header.hpp"
#include "bag/topics.hpp"

namespace littermap::bag::sensor_messages {
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

msg::TFMessage StaticTransforms(TimestampNs stamp_ns, const Eigen::Isometry3d& T_base_laser,
                                const Eigen::Isometry3d& T_base_optical) {
  return msg::TFMessage{{TransformFromBase(stamp_ns, frames::kLaser, T_base_laser),
                         TransformFromBase(stamp_ns, frames::kCamera, T_base_optical)}};
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

}  // namespace littermap::bag::sensor_messages
