#pragma once
// std_msgs/Header from littermap's nanosecond time stamps (builtin_interfaces/Time holds
// int32 seconds and uint32 nanoseconds; callers keep stamps inside that range).

#include <cstdint>
#include <string>
#include <utility>

#include "capture/ros_messages.hpp"
#include "core/time.hpp"

namespace littermap {

inline msg::Header MakeHeader(TimestampNs stamp_ns, std::string frame_id) {
  msg::Header header;
  header.stamp.sec = static_cast<std::int32_t>(stamp_ns / kNanosecondsPerSecond);
  header.stamp.nanosec = static_cast<std::uint32_t>(stamp_ns % kNanosecondsPerSecond);
  header.frame_id = std::move(frame_id);
  return header;
}

}  // namespace littermap
