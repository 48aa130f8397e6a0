#pragma once
// Time stamps: signed nanoseconds since the Unix epoch, as rosbag2 stores them.

#include <cmath>
#include <cstdint>

namespace littermap {

using TimestampNs = std::int64_t;

constexpr TimestampNs kNanosecondsPerSecond = 1'000'000'000;

inline double ToSeconds(TimestampNs t) { return static_cast<double>(t) * 1e-9; }

inline TimestampNs FromSeconds(double seconds) {
  return static_cast<TimestampNs>(std::llround(seconds * 1e9));
}

}  // namespace littermap
