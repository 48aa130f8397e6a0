#pragma once
// The odometry of the last moments, read at a sensor's stamp: the two readings around the stamp
// interpolated. Wheels at 50 Hz and a laser at 40 Hz put the latest reading up to 20 ms before a
// scan: a centimetre of driving and, turning at 1 rad/s, more than a degree of heading that the
// scan matcher would otherwise have to explain.

#include <deque>
#include <optional>
#include <utility>

#include "core/time.hpp"
#include "reconstruct/gyro_odometry.hpp"

namespace littermap::reconstruct {

class OdometryHistory {
 public:
  // max_age_s: a stamp outside the readings takes the nearest one at most this far from it.
  explicit OdometryHistory(double max_age_s);

  // Readings in time order; an older or equal stamp than the newest is ignored.
  void Add(TimestampNs stamp_ns, const GyroOdometryPose& pose);
  // True once a reading at or after stamp_ns has arrived: At(stamp_ns) will not change.
  bool Covers(TimestampNs stamp_ns) const;
  // The pose at stamp_ns: interpolated between the readings around it, else the nearest reading
  // if within max_age_s, else nothing.
  std::optional<GyroOdometryPose> At(TimestampNs stamp_ns) const;
  // Forgets the readings no longer needed for stamps at or after stamp_ns.
  void DropBefore(TimestampNs stamp_ns);

 private:
  double max_age_s_;
  std::deque<std::pair<TimestampNs, GyroOdometryPose>> readings_;
};

}  // namespace littermap::reconstruct
