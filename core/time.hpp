#pragma once
// Time stamps: signed nanoseconds since the Unix epoch, as rosbag2 stores them.

#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <limits>
#include <optional>
#include <string>

namespace littermap {

using TimestampNs = std::int64_t;

constexpr TimestampNs kNanosecondsPerSecond = 1'000'000'000;

inline double ToSeconds(TimestampNs t) { return static_cast<double>(t) * 1e-9; }

// later - earlier, or nullopt when stamps from a damaged or hostile file lie further apart than
// 64-bit nanoseconds reach (292 years).
inline std::optional<TimestampNs> CheckedDifference(TimestampNs later, TimestampNs earlier) {
  TimestampNs difference = 0;
  if (__builtin_sub_overflow(later, earlier, &difference)) return std::nullopt;
  return difference;
}

// later - earlier, clamped to the 64-bit range.
inline TimestampNs SaturatingDifference(TimestampNs later, TimestampNs earlier) {
  if (const auto difference = CheckedDifference(later, earlier)) return *difference;
  return later > earlier ? std::numeric_limits<TimestampNs>::max()
                         : std::numeric_limits<TimestampNs>::min();
}

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
