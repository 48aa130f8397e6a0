#pragma once
// Time stamps: signed nanoseconds since the Unix epoch, as rosbag2 stores them.

#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <string>

namespace littermap {

using TimestampNs = std::int64_t;

constexpr TimestampNs kNanosecondsPerSecond = 1'000'000'000;

inline double ToSeconds(TimestampNs t) { return static_cast<double>(t) * 1e-9; }

inline TimestampNs FromSeconds(double seconds) {
  return static_cast<TimestampNs>(std::llround(seconds * 1e9));
}

// The host's wall clock, Unix epoch: the receive time of live sensor data.
inline TimestampNs HostNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// Unix seconds as UTC text for people, with a strftime format ("%Y-%m-%d %H:%M" by default).
inline std::string FormatUtc(double unix_s, const char* format = "%Y-%m-%d %H:%M") {
  const auto seconds = static_cast<std::time_t>(std::floor(unix_s));
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  char text[64];
  return std::string(text, std::strftime(text, sizeof text, format, &utc));
}

}  // namespace littermap
