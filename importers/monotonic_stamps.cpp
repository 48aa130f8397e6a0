#include "importers/monotonic_stamps.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace littermap::importers {
namespace {

bool InRange(double stamp_s, const MonotonicStampOptions& options) {
  return stamp_s >= 0 && stamp_s <= options.max_stamp_s;  // false for NaN
}

// Stamps that need repair: those out of range, and those not after the last stamp in range.
std::size_t BadStamps(std::span<const double> raw_s, const MonotonicStampOptions& options) {
  std::size_t count = 0;
  const double* last = nullptr;
  for (const double& stamp_s : raw_s) {
    if (!InRange(stamp_s, options)) {
      ++count;
      continue;
    }
    if (last != nullptr && !(stamp_s > *last)) ++count;
    last = &stamp_s;
  }
  return count;
}

std::uint64_t CountChanged(std::span<const double> raw_s, const std::vector<TimestampNs>& stamps) {
  std::uint64_t changed = 0;
  for (std::size_t i = 0; i < raw_s.size(); ++i) {
    if (!std::isfinite(raw_s[i]) || stamps[i] != FromSeconds(raw_s[i])) ++changed;
  }
  return changed;
}

}  // namespace

MonotonicStampResult MakeMonotonicStamps(std::span<const double> raw_s,
                                         const MonotonicStampOptions& options) {
  if (!(options.min_step_s > 0) || !(options.nominal_interval_s > 0) ||
      !(options.synthetic_start_s > 0) || !(options.max_stamp_s > options.synthetic_start_s)) {
    throw UsageError(
        "time stamp repair: steps, intervals and the start must be positive, the maximum "
        "after the start");
  }
  MonotonicStampResult result;
  result.stamps_ns.reserve(raw_s.size());
  if (raw_s.empty()) return result;

  result.out_of_range = static_cast<std::uint64_t>(std::count_if(
      raw_s.begin(), raw_s.end(), [&](double stamp_s) { return !InRange(stamp_s, options); }));
  const double bad_fraction = raw_s.size() > 1 ? static_cast<double>(BadStamps(raw_s, options)) /
                                                     static_cast<double>(raw_s.size() - 1)
                                               : 0.0;
  // Leading stamps out of range go just before the first one in range, if there is room.
  const auto first_in_range = std::find_if(
      raw_s.begin(), raw_s.end(), [&](double stamp_s) { return InRange(stamp_s, options); });
  const auto leading = static_cast<double>(first_in_range - raw_s.begin());
  const bool room_before =
      first_in_range != raw_s.end() && *first_in_range - leading * options.min_step_s > 0;
  if (bad_fraction > options.unusable_fraction || !room_before) {
    // Keep the log's (coarse) start if it has one, so the bag is dated roughly right.
    const TimestampNs start = FromSeconds(raw_s.front() > 0 && InRange(raw_s.front(), options)
                                              ? raw_s.front()
                                              : options.synthetic_start_s);
    const TimestampNs interval = FromSeconds(options.nominal_interval_s);
    for (std::size_t i = 0; i < raw_s.size(); ++i) {
      result.stamps_ns.push_back(start + static_cast<TimestampNs>(i) * interval);
    }
    result.synthesised = true;
  } else {
    const TimestampNs min_step = std::max<TimestampNs>(1, FromSeconds(options.min_step_s));
    for (std::size_t i = 0; i < raw_s.size(); ++i) {
      TimestampNs stamp = InRange(raw_s[i], options)
                              ? FromSeconds(raw_s[i])
                              : FromSeconds(*first_in_range - (leading - static_cast<double>(i)) *
                                                                  options.min_step_s);
      if (i > 0 && stamp <= result.stamps_ns.back()) stamp = result.stamps_ns.back() + min_step;
      result.stamps_ns.push_back(stamp);
    }
  }
  result.changed = CountChanged(raw_s, result.stamps_ns);
  return result;
}

}  // namespace littermap::importers
