#include "reconstruct/moving_echo_filter.hpp"

#include <utility>

#include "core/error.hpp"

namespace littermap::reconstruct {

void MovingEchoFilterOptions::Validate() const {
  if (!(min_interval_s > 0) || !(static_tolerance_m > 0) || !(static_tolerance_per_m >= 0) ||
      !(max_shift_m > static_tolerance_m)) {
    throw UsageError(
        "moving echoes: need min_interval_s > 0, static_tolerance_m > 0, "
        "static_tolerance_per_m >= 0 and max_shift_m > static_tolerance_m");
  }
  if (!(min_relief_m >= 0) || !(relief_window_m > 0)) {
    throw UsageError("moving echoes: need min_relief_m >= 0 and relief_window_m > 0");
  }
  if (!(max_moving_fraction > 0 && max_moving_fraction <= 1)) {
    throw UsageError("moving echoes: max_moving_fraction must be in (0, 1]");
  }
}

MovingEchoFilter::MovingEchoFilter(const MovingEchoFilterOptions& options) : options_(options) {
  options_.Validate();
}

MovingEchoFilter::Earlier* MovingEchoFilter::Reference(TimestampNs stamp_ns) {
  while (earlier_.size() >= 2 &&
         ToSeconds(stamp_ns - earlier_[1].stamp_ns) >= options_.min_interval_s) {
    earlier_.pop_front();
  }
  return !earlier_.empty() &&
                 ToSeconds(stamp_ns - earlier_.front().stamp_ns) >= options_.min_interval_s
             ? &earlier_.front()
             : nullptr;
}

void MovingEchoFilter::Remember(TimestampNs stamp_ns, const PlanarPose& T_odom_base,
                                Points2 points_base) {
  Reference(stamp_ns);  // drops the scans no later one will compare with
  earlier_.push_back({stamp_ns, T_odom_base, std::move(points_base), nullptr});
}

MovingEchoResult MovingEchoFilter::Filter(TimestampNs stamp_ns, const PlanarPose& T_odom_base,
                                          Points2 points_base) {
  Earlier* reference = Reference(stamp_ns);
  MovingEchoResult result;
  if (reference == nullptr) {
    result.points_base = points_base;
  } else {
    if (!reference->echoes) {
      reference->echoes = std::make_shared<const IcpTarget>(reference->points_base, Points2{});
    }
    const PlanarPose T_earlier_now = Between(reference->T_odom_base, T_odom_base);
    const double max_sq = options_.max_shift_m * options_.max_shift_m;
    result.points_base.reserve(points_base.size());
    for (const Eigen::Vector2d& p : points_base) {
      const double tolerance =
          options_.static_tolerance_m + options_.static_tolerance_per_m * p.norm();
      std::size_t index = 0;
      double distance_sq = 0;
      if (reference->echoes->NearestWithin(Transform(T_earlier_now, p), max_sq, &index,
                                           &distance_sq) &&
          distance_sq > tolerance * tolerance && distance_sq < max_sq) {
        ++result.moving;
        continue;
      }
      result.points_base.push_back(p);
    }
    if (!points_base.empty() &&
        static_cast<double>(result.moving) >
            options_.max_moving_fraction * static_cast<double>(points_base.size())) {
      result.given_up = true;
    }
  }
  earlier_.push_back({stamp_ns, T_odom_base, std::move(points_base), nullptr});
  return result;
}

}  // namespace littermap::reconstruct
