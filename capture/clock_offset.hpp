#pragma once
// Maps a sensor's own clock to host time. Arrival is always later than the measurement, so over
// the first `samples` readings the smallest (arrival − sensor time) is the tightest offset; it is
// then held, so stamps stay as regular as the sensor's clock.

#include <algorithm>

#include "core/time.hpp"

namespace littermap::capture {

class ClockOffset {
 public:
  explicit ClockOffset(int samples) : samples_(samples) {}

  // Host time of a reading the sensor stamped sensor_ns that arrived at host time arrival_ns.
  TimestampNs ToHost(TimestampNs sensor_ns, TimestampNs arrival_ns) {
    if (seen_ < samples_) {
      const TimestampNs sample = arrival_ns - sensor_ns;
      offset_ns_ = seen_ == 0 ? sample : std::min(offset_ns_, sample);
      ++seen_;
    }
    return sensor_ns + offset_ns_;
  }

  bool known() const { return seen_ > 0; }
  TimestampNs offset_ns() const { return offset_ns_; }

 private:
  int samples_;
  int seen_ = 0;
  TimestampNs offset_ns_ = 0;
};

}  // namespace littermap::capture
