#pragma once
// A survey route for benchmarks: a 15-minute lawn-mower pattern at 0.5 m/s sampled at 10 Hz
// (9000 poses), lanes of lane_length_m, 6 m apart, from (x0_m, y0_m) heading east.

#include <vector>

#include "core/planar_pose.hpp"

namespace littermap::bench {

inline std::vector<PlanarPose> LawnMowerRun(double x0_m, double y0_m, double lane_length_m) {
  std::vector<PlanarPose> run;
  for (int i = 0; i < 9000; ++i) {
    const double s = 0.05 * i;
    const int lane = static_cast<int>(s / lane_length_m);
    const double along = s - lane_length_m * lane;
    const bool east = lane % 2 == 0;
    run.push_back({east ? x0_m + along : x0_m + lane_length_m - along, y0_m + 6.0 * lane,
                   east ? 0.0 : 3.14159});
  }
  return run;
}

}  // namespace littermap::bench
