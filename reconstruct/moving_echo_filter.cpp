#include "reconstruct/moving_echo_filter.hpp"

#include <algorithm>
#include <utility>

#include "core/error.hpp"

namespace littermap::reconstruct {

void MovingEchoFilterOptions::Validate() const {
  if (!(min_interval_s > 0) || !(long_interval_s >= 0) || !(static_tolerance_m > 0) ||
      !(static_tolerance_per_m >= 0) || !(max_shift_m > static_tolerance_m)) {
    throw UsageError(
        "moving echoes: need min_interval_s > 0, long_interval_s >= 0, static_tolerance_m > 0, "
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

void MovingEchoFilter::Forget(TimestampNs stamp_ns) {
  const double keep_s = std::max(options_.min_interval_s, options_.long_interval_s);
  while (earlier_.size() >= 2 && ToSeconds(stamp_ns - earlier_[1].stamp_ns) >= keep_s) {
    earlier_.pop_front();
  }
}

MovingEchoFilter::Earlier* MovingEchoFilter::Reference(TimestampNs stamp_ns, double interval_s) {
  for (auto it = earlier_.rbegin(); it != earlier_.rend(); ++it) {
    if (ToSeconds(stamp_ns - it->stamp_ns) >= interval_s) return &*it;
  }
  return nullptr;
}

const IcpTarget& MovingEchoFilter::EchoesOf(Earlier& earlier) {
  if (!earlier.echoes) {
    earlier.echoes = std::make_shared<const IcpTarget>(earlier.points_base, Points2{});
  }
  return *earlier.echoes;
}

bool MovingEchoFilter::Beside(const IcpTarget& echoes, const Eigen::Vector2d& p_earlier,
                              double tolerance_sq) const {
  const double max_sq = options_.max_shift_m * options_.max_shift_m;
  std::size_t index = 0;
  double distance_sq = 0;
  return echoes.NearestWithin(p_earlier, max_sq, &index, &distance_sq) &&
         distance_sq > tolerance_sq && distance_sq < max_sq;
}

void MovingEchoFilter::Remember(TimestampNs stamp_ns, const PlanarPose& T_odom_base,
                                Points2 points_base) {
  Forget(stamp_ns);
  earlier_.push_back({stamp_ns, T_odom_base, std::move(points_base), nullptr});
}

MovingEchoResult MovingEchoFilter::Filter(TimestampNs stamp_ns, const PlanarPose& T_odom_base,
                                          Points2 points_base) {
  Forget(stamp_ns);
  Earlier* recent = Reference(stamp_ns, options_.min_interval_s);
  Earlier* older =
      options_.long_interval_s > 0 ? Reference(stamp_ns, options_.long_interval_s) : nullptr;
  if (older == recent) older = nullptr;
  MovingEchoResult result;
  if (recent == nullptr) {
    result.points_base = points_base;
  } else {
    const IcpTarget& recent_echoes = EchoesOf(*recent);
    const IcpTarget* older_echoes = older != nullptr ? &EchoesOf(*older) : nullptr;
    const PlanarPose T_recent_now = Between(recent->T_odom_base, T_odom_base);
    const PlanarPose T_older_now =
        older != nullptr ? Between(older->T_odom_base, T_odom_base) : PlanarPose{};
    result.points_base.reserve(points_base.size());
    for (const Eigen::Vector2d& p : points_base) {
      const double tolerance =
          options_.static_tolerance_m + options_.static_tolerance_per_m * p.norm();
      const double tolerance_sq = tolerance * tolerance;
      if (Beside(recent_echoes, Transform(T_recent_now, p), tolerance_sq) ||
          (older_echoes != nullptr &&
           Beside(*older_echoes, Transform(T_older_now, p), tolerance_sq))) {
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
