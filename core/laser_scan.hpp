#pragma once
// A planar laser scan in the laser's own frame, independent of any message format: beam i points
// at angle_min_rad + i * angle_increment_rad (counter-clockwise from the laser's x axis).
// Readings follow REP 117: a beam without an echo within range is +infinity; a reading below
// range_min_m is too close to measure.

#include <cstddef>
#include <vector>

#include "core/time.hpp"

namespace littermap {

struct LaserScan {
  TimestampNs stamp_ns = 0;  // time of the first beam
  double angle_min_rad = 0;
  double angle_increment_rad = 0;
  double range_min_m = 0;
  double range_max_m = 0;
  double scan_time_s = 0;  // time between scans (0 when unknown)
  std::vector<float> ranges_m;

  double AngleOf(std::size_t beam) const {
    return angle_min_rad + static_cast<double>(beam) * angle_increment_rad;
  }
  double angle_max_rad() const {
    return ranges_m.empty() ? angle_min_rad : AngleOf(ranges_m.size() - 1);
  }
  bool IsValid(std::size_t beam) const {
    const double r = ranges_m[beam];
    return r >= range_min_m && r <= range_max_m;
  }
};

}  // namespace littermap
