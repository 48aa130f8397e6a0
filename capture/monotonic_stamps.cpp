#include "capture/monotonic_stamps.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace littermap {
namespace {

std::size_t NonIncreasingSteps(std::span<const double> raw_s) {
  std::size_t count = 0;
  for (std::size_t i = 1; i < raw_s.size(); ++i) {
    if (!(raw_s[i] > raw_s[i - 1])) ++count;
  }
  return count;
}

std::uint64_t CountChanged(std::span<const double> raw_s, const std::vector<TimestampNs>& stamps) {
  std::uint64_t changed = 0;
  for (std::size_t i = 0; i < raw_s.size(); ++i) {
    if (stamps[i] != FromSeconds(raw_s[i])) ++changed;
  }
  return changed;
}

}  // namespace

MonotonicStampResult MakeMonotonicStamps(std::span<const double> raw_s,
                                         const MonotonicStampOptions& options) {
  if (!(options.min_step_s > 0) || !(options.nominal_interval_s > 0) ||
      !(options.synthetic_start_s > 0)) {
    throw UsageError("time stamp repair: steps, intervals and the start must be positive");
  }
  MonotonicStampResult result;
  result.stamps_ns.reserve(raw_s.size());
  if (raw_s.empty()) return result;

  const double bad_fraction = raw_s.size() > 1 ? static_cast<double>(NonIncreasingSteps(raw_s)) /
                                                     static_cast<double>(raw_s.size() - 1)
                                               : 0.0;
  if (bad_fraction > options.unusable_fraction) {
    // Keep the log's (coarse) start if it has one, so the bag is dated roughly right.
    const TimestampNs start =
        FromSeconds(raw_s.front() > 0 ? raw_s.front() : options.synthetic_start_s);
    const TimestampNs interval = FromSeconds(options.nominal_interval_s);
    for (std::size_t i = 0; i < raw_s.size(); ++i) {
      result.stamps_ns.push_back(start + static_cast<TimestampNs>(i) * interval);
    }
    result.synthesised = true;
  } else {
    const TimestampNs min_step = std::max<TimestampNs>(1, FromSeconds(options.min_step_s));
    for (std::size_t i = 0; i < raw_s.size(); ++i) {
      TimestampNs stamp = FromSeconds(raw_s[i]);
      if (i > 0 && stamp <= result.stamps_ns.back()) stamp = result.stamps_ns.back() + min_step;
      result.stamps_ns.push_back(stamp);
    }
  }
  result.changed = CountChanged(raw_s, result.stamps_ns);
  return result;
}

}  // namespace littermap
