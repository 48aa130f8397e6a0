#include "reconstruct/odometry_history.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace littermap::reconstruct {
namespace {

GyroOdometryPose Interpolate(const GyroOdometryPose& a, const GyroOdometryPose& b,
                             double fraction) {
  const PlanarPose& p = a.T_odom_base;
  const PlanarPose& q = b.T_odom_base;
  GyroOdometryPose pose;
  pose.T_odom_base = {p.x_m + fraction * (q.x_m - p.x_m), p.y_m + fraction * (q.y_m - p.y_m),
                      WrapAngle(p.theta_rad + fraction * WrapAngle(q.theta_rad - p.theta_rad))};
  pose.heading_from_gyro = a.heading_from_gyro && b.heading_from_gyro;
  pose.z_m = a.z_m + fraction * (b.z_m - a.z_m);
  return pose;
}

}  // namespace

OdometryHistory::OdometryHistory(double max_age_s) : max_age_s_(max_age_s) {
  if (!(max_age_s > 0)) throw UsageError("odometry history: max_age_s must be > 0");
}

void OdometryHistory::Add(TimestampNs stamp_ns, const GyroOdometryPose& pose) {
  if (!readings_.empty() && stamp_ns <= readings_.back().first) return;
  readings_.emplace_back(stamp_ns, pose);
}

bool OdometryHistory::Covers(TimestampNs stamp_ns) const {
  return !readings_.empty() && readings_.back().first >= stamp_ns;
}

std::optional<GyroOdometryPose> OdometryHistory::At(TimestampNs stamp_ns) const {
  if (readings_.empty()) return std::nullopt;
  const auto after = std::lower_bound(
      readings_.begin(), readings_.end(), stamp_ns,
      [](const auto& reading, TimestampNs stamp) { return reading.first < stamp; });
  if (after != readings_.end() && after->first == stamp_ns) return after->second;
  if (after != readings_.end() && after != readings_.begin()) {
    const auto& [t0, before_pose] = *std::prev(after);
    const double fraction =
        static_cast<double>(stamp_ns - t0) / static_cast<double>(after->first - t0);
    return Interpolate(before_pose, after->second, fraction);
  }
  const auto& nearest = after == readings_.end() ? readings_.back() : readings_.front();
  if (std::abs(ToSeconds(stamp_ns - nearest.first)) <= max_age_s_) return nearest.second;
  return std::nullopt;
}

void OdometryHistory::DropBefore(TimestampNs stamp_ns) {
  // Keep the last reading before stamp_ns: it brackets stamps just after it.
  while (readings_.size() >= 2 && readings_[1].first <= stamp_ns) readings_.pop_front();
}

}  // namespace littermap::reconstruct
