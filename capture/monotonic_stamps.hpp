#pragma once
// Strictly increasing time stamps from a log's raw ones. Real logs break monotonicity in two
// ways: some carry no time at all (every stamp 0, or one coarse value printed with 6 significant
// digits), others have a few repeated or slightly backward stamps. A bag needs increasing
// receive times, so the first kind gets stamps synthesised at a nominal rate and the second has
// each offending stamp moved just after its predecessor. The result says how many changed so
// the caller can tell the user.

#include <cstdint>
#include <span>
#include <vector>

#include "core/time.hpp"

namespace littermap {

struct MonotonicStampOptions {
  double min_step_s = 0.001;        // a stamp not after its predecessor moves to predecessor + this
  double nominal_interval_s = 1.0;  // spacing of synthesised stamps
  double synthetic_start_s = 1.0;   // first synthesised stamp when the log has none usable (> 0,
                                    // because ROS tools read a zero stamp as "no time")
  double unusable_fraction = 0.5;   // more non-increasing steps than this: synthesise all
};

struct MonotonicStampResult {
  std::vector<TimestampNs> stamps_ns;
  std::uint64_t changed = 0;  // stamps that differ from the raw ones (beyond rounding to ns)
  bool synthesised = false;   // the raw stamps were unusable and all were replaced
};

// Throws UsageError for non-positive steps or intervals.
MonotonicStampResult MakeMonotonicStamps(std::span<const double> raw_s,
                                         const MonotonicStampOptions& options = {});

}  // namespace littermap
