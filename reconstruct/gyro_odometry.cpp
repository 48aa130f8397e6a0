#include "reconstruct/gyro_odometry.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"

namespace littermap::reconstruct {

void GyroOdometryOptions::Validate() const {
  if (!(max_gyro_gap_s > 0) || !(slope_window_m > 0) || !(max_pitch_off_slope_rad > 0)) {
    throw UsageError(
        "gyro odometry: max_gyro_gap_s, slope_window_m and max_pitch_off_slope_rad must be > 0");
  }
}

GyroOdometry::GyroOdometry(const GyroOdometryOptions& options) : options_(options) {
  options_.Validate();
}

void GyroOdometry::AddYawRate(TimestampNs stamp_ns, double yaw_rate_rad_s) {
  if (!std::isfinite(yaw_rate_rad_s)) return;
  if (first_rate_ns_) {
    if (stamp_ns <= last_rate_ns_) return;
    const double dt = ToSeconds(stamp_ns - last_rate_ns_);
    if (dt > options_.max_gyro_gap_s) {
      first_rate_ns_ = stamp_ns;  // a gap: the yaw after it is unrelated to the yaw before
    } else {
      yaw_rad_ += 0.5 * (last_rate_rad_s_ + yaw_rate_rad_s) * dt;
    }
  } else {
    first_rate_ns_ = stamp_ns;
  }
  last_rate_ns_ = stamp_ns;
  last_rate_rad_s_ = yaw_rate_rad_s;
}

std::optional<double> GyroOdometry::YawAt(TimestampNs stamp_ns) const {
  if (!first_rate_ns_ || stamp_ns < *first_rate_ns_) return std::nullopt;
  // Readings of the two sensors interleave: the last rate holds for a moment either way.
  const double ahead_s = ToSeconds(stamp_ns - last_rate_ns_);
  if (std::abs(ahead_s) > options_.max_gyro_gap_s) return std::nullopt;
  return yaw_rad_ + last_rate_rad_s_ * ahead_s;
}

void GyroOdometry::AddPitch(double pitch_rad) {
  if (std::isfinite(pitch_rad)) pitch_rad_ = pitch_rad;
}

std::optional<double> GyroOdometry::SlopePitch() {
  if (!pitch_rad_) return std::nullopt;
  recent_pitch_.emplace_back(path_m_, *pitch_rad_);
  while (path_m_ - recent_pitch_.front().first > options_.slope_window_m) {
    recent_pitch_.pop_front();
  }
  std::vector<double> pitches;
  pitches.reserve(recent_pitch_.size());
  for (const auto& [path_m, pitch_rad] : recent_pitch_) pitches.push_back(pitch_rad);
  const auto middle = pitches.begin() + static_cast<std::ptrdiff_t>(pitches.size() / 2);
  std::nth_element(pitches.begin(), middle, pitches.end());
  return std::abs(*pitch_rad_ - *middle) <= options_.max_pitch_off_slope_rad ? *pitch_rad_
                                                                             : *middle;
}

GyroOdometryPose GyroOdometry::AddOdometry(TimestampNs stamp_ns, const PlanarPose& T_odom_base) {
  GyroOdometryPose pose;
  if (last_ && stamp_ns <= last_->stamp_ns) {  // out of order: passed on, nothing learnt
    pose.T_odom_base = Fused(T_odom_base);
    pose.z_m = z_m_;
    return pose;
  }
  const Reading now{stamp_ns, T_odom_base, YawAt(stamp_ns)};
  const std::optional<double> pitch_rad = SlopePitch();
  if (last_) {
    PlanarPose step = Between(last_->T_wheels_base, T_odom_base);
    path_m_ += std::hypot(step.x_m, step.y_m);
    if (pitch_rad && last_pitch_rad_) {
      // base_link's x axis climbs at -sin(pitch).
      z_m_ -= step.x_m * std::sin(0.5 * (*pitch_rad + *last_pitch_rad_));
    }
    // The yaw is continuous between the two readings only if no gap restarted it in between.
    if (now.yaw_rad && last_->yaw_rad && *first_rate_ns_ <= last_->stamp_ns) {
      step.theta_rad = WrapAngle(*now.yaw_rad - *last_->yaw_rad);
      const PlanarPose fused = Compose(Fused(last_->T_wheels_base), step);
      T_fused_wheels_ = Compose(fused, Inverse(T_odom_base));
      turned_ = true;
      pose.heading_from_gyro = true;
    }
  }
  last_ = now;
  last_pitch_rad_ = pitch_rad;
  pose.T_odom_base = Fused(T_odom_base);
  pose.z_m = z_m_;
  return pose;
}

PlanarPose GyroOdometry::Fused(const PlanarPose& T_wheels_base) const {
  // Until the gyro turns a step, the wheels' pose exactly as read.
  return turned_ ? Compose(T_fused_wheels_, T_wheels_base) : T_wheels_base;
}

}  // namespace littermap::reconstruct
