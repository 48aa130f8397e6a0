#pragma once
// How much the ground rose and fell under the robot over the last stretch of its path: the
// spread of the odometry's height (GyroOdometry climbs the distance driven at the IMU's pitch)
// over the last window_m of path. Where the relief within the laser's reach is larger than the
// scanner's height, the scan plane cuts the ground ahead and behind (MovingEchoFilter).

#include <deque>

#include "core/planar_pose.hpp"

namespace littermap::reconstruct {

class TerrainRelief {
 public:
  explicit TerrainRelief(double window_m) : window_m_(window_m) {}

  // The odometry's pose and height at the next scan; returns the relief (max - min height, m)
  // over the last window_m of path up to it.
  double Add(const PlanarPose& T_odom_base, double z_m);

 private:
  struct Sample {
    double path_m = 0;
    double z_m = 0;
  };
  double window_m_;
  double path_m_ = 0;
  bool started_ = false;
  PlanarPose last_;
  std::deque<Sample> samples_;
};

}  // namespace littermap::reconstruct
