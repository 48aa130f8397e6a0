#pragma once
// Strictly increasing time stamps from a log's raw ones. Real logs break monotonicity in two
// ways: some carry no time at all (every stamp 0, or one coarse value printed with 6 significant
// digits), others have a few repeated or slightly backward stamps. A bag needs increasing
// receive times, so the first kind gets stamps synthesised at a nominal rate and the second has
// each offending stamp moved just after its predecessor. A stamp outside the range a bag can
// hold (negative, not a number, or past 2e9 s: a clock that wrapped or was never set) carries no
// time either and is repaired the same way; a log that starts with one has every stamp
// synthesised. The result says how many changed so the caller can tell the user.

#include <cstdint>
#include <span>
#include <vector>

#include "core/time.hpp"

namespace littermap::importers {

struct MonotonicStampOptions {
  double min_step_s = 0.001;        // a stamp not after its predecessor moves to predecessor + this
  double nominal_interval_s = 1.0;  // spacing of synthesised stamps
  double synthetic_start_s = 1.0;   // first synthesised stamp when the log has none usable (> 0,
                                    // because ROS tools read a zero stamp as "no time")
  double unusable_fraction = 0.5;   // more non-increasing steps than this: synthesise all
  double max_stamp_s = 2e9;         // later stamps are out of range (msg::Time's int32 seconds)
};

struct MonotonicStampResult {
  std::vector<TimestampNs> stamps_ns;
  std::uint64_t changed = 0;       // stamps that differ from the raw ones (beyond rounding to ns)
  bool synthesised = false;        // the raw stamps were unusable and all were replaced
  std::uint64_t out_of_range = 0;  // raw stamps outside 0 .. max_stamp_s (or not a number)
};

// Throws UsageError for non-positive steps, intervals or maximum.
MonotonicStampResult MakeMonotonicStamps(std::span<const double> raw_s,
                                         const MonotonicStampOptions& options = {});

}  // namespace littermap::importers
