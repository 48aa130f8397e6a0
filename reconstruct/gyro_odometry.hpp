#pragma once
// Wheel odometry with its heading taken from the IMU's yaw rate ("gyrodometry"): wheels measure
// the distance driven well and the heading poorly (track width, slip on grass), a gyro the
// reverse. Every odometry reading adds the wheels' translation since the last one, turned by the
// heading change the gyro integrated over the same interval. Where the gyro has a gap (no
// reading within max_gyro_gap_s), that step keeps the wheels' own heading change.
// With the IMU's pitch, the distance driven also climbs: the height above the first reading, so
// a planar SLAM on hills can still say where the robot is in 3D. Terrain slopes change over
// metres; a pitch far from the median of the last metres is a root or stone under one wheel,
// which tilts the robot without lifting it, and the median stands in for it.

#include <deque>
#include <optional>
#include <utility>

#include "core/planar_pose.hpp"
#include "core/time.hpp"

namespace littermap::reconstruct {

struct GyroOdometryOptions {
  double max_gyro_gap_s = 0.1;  // longer between two yaw rates: no gyro heading there
  double slope_window_m = 2.0;  // the median pitch over this much of the path is the slope
  double max_pitch_off_slope_rad = 0.035;  // further from it: a bump, not the slope
  void Validate() const;
};

struct GyroOdometryPose {
  PlanarPose T_odom_base;          // the fused odometry
  bool heading_from_gyro = false;  // the step to it turned by the gyro
  double z_m = 0;                  // height above the first reading (0 without pitch)
};

class GyroOdometry {
 public:
  explicit GyroOdometry(const GyroOdometryOptions& options = {});

  // A yaw rate about base_link's z axis (IMU angular velocity); readings out of order are
  // ignored.
  void AddYawRate(TimestampNs stamp_ns, double yaw_rate_rad_s);
  // The base's pitch against gravity (IMU orientation, ROS: positive puts the nose down); the
  // latest holds for the next odometry step.
  void AddPitch(double pitch_rad);
  // The fused pose at a wheel odometry reading. The fused odometry starts where the wheels are
  // and stays on them until the gyro turns a step; a reading out of order is passed on (moved
  // like the others) but changes nothing.
  GyroOdometryPose AddOdometry(TimestampNs stamp_ns, const PlanarPose& T_odom_base);

 private:
  // The integrated yaw at stamp_ns, if the gyro covers it.
  std::optional<double> YawAt(TimestampNs stamp_ns) const;
  // The fused pose of a wheels' pose.
  PlanarPose Fused(const PlanarPose& T_wheels_base) const;
  // The latest pitch, or the slope's where it is a bump's; records it in recent_pitch_.
  std::optional<double> SlopePitch();

  GyroOdometryOptions options_;
  // Integrated yaw (trapezoidal) up to the last rate, and since when it is without gaps.
  std::optional<TimestampNs> first_rate_ns_;
  TimestampNs last_rate_ns_ = 0;
  double last_rate_rad_s_ = 0;
  double yaw_rad_ = 0;
  struct Reading {
    TimestampNs stamp_ns = 0;
    PlanarPose T_wheels_base;
    std::optional<double> yaw_rad;
  };
  std::optional<Reading> last_;
  // The fused odometry is the wheels' moved by this, which each gyro-turned step updates.
  PlanarPose T_fused_wheels_;
  bool turned_ = false;
  double z_m_ = 0;
  // The pitch climbed at since the last odometry reading; the pitches over the last
  // slope_window_m of path (distance driven, pitch).
  std::optional<double> pitch_rad_, last_pitch_rad_;
  std::deque<std::pair<double, double>> recent_pitch_;
  double path_m_ = 0;
};

}  // namespace littermap::reconstruct
