#pragma once
// How far the base rocks off the ground's slope: the latest tilt's distance from the median tilt
// (roll and pitch each) of the scans over the last window_s. Climbing a hill tilts the base
// steadily and the median follows; a root or a kerb rocks it for a fraction of a second, while
// the scanner sweeps its plane through trunks at changing heights and angles.

#include <deque>

#include "core/time.hpp"
#include "reconstruct/scan_points.hpp"

namespace littermap::reconstruct {

class TiltRocking {
 public:
  explicit TiltRocking(double window_s) : window_s_(window_s) {}

  // The tilt at the next scan (stamps increasing).
  void Add(TimestampNs stamp_ns, const Tilt& tilt);
  // The latest tilt's angle (rad) from the median tilt of the scans within window_s up to it,
  // that one included; 0 before any. Asked at key frames only, so the median is not taken for
  // every scan.
  double LatestRockingRad() const;

 private:
  struct Sample {
    TimestampNs stamp_ns = 0;
    Tilt tilt;
  };
  double window_s_;
  std::deque<Sample> samples_;
};

}  // namespace littermap::reconstruct
