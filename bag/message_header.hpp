#pragma once
// std_msgs/Header to and from littermap's nanosecond time stamps (builtin_interfaces/Time holds
// int32 seconds and uint32 nanoseconds; callers keep stamps inside that range), and
// geometry_msgs rotations and transforms as Eigen types.

#include <cstdint>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "bag/ros_messages.hpp"
#include "core/time.hpp"

namespace littermap::bag {

inline msg::Header MakeHeader(TimestampNs stamp_ns, std::string frame_id) {
  msg::Header header;
  header.stamp.sec = static_cast<std::int32_t>(stamp_ns / kNanosecondsPerSecond);
  header.stamp.nanosec = static_cast<std::uint32_t>(stamp_ns % kNanosecondsPerSecond);
  header.frame_id = std::move(frame_id);
  return header;
}

inline TimestampNs StampOf(const msg::Header& header) {
  return static_cast<TimestampNs>(header.stamp.sec) * kNanosecondsPerSecond +
         static_cast<TimestampNs>(header.stamp.nanosec);
}

inline Eigen::Quaterniond ToEigen(const msg::Quaternion& q) { return {q.w, q.x, q.y, q.z}; }
inline msg::Quaternion ToMsg(const Eigen::Quaterniond& q) { return {q.x(), q.y(), q.z(), q.w()}; }

inline Eigen::Isometry3d ToIsometry(const msg::Transform& transform) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = ToEigen(transform.rotation).normalized().toRotationMatrix();
  T.translation() =
      Eigen::Vector3d(transform.translation.x, transform.translation.y, transform.translation.z);
  return T;
}

}  // namespace littermap::bag
