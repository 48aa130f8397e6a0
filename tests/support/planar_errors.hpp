#pragma once
// The largest position error between two equally long sequences of planar poses.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "core/planar_pose.hpp"

namespace littermap::test {

inline double MaxPositionError(const std::vector<PlanarPose>& a, const std::vector<PlanarPose>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::hypot(a[i].x_m - b[i].x_m, a[i].y_m - b[i].y_m));
  }
  return worst;
}

}  // namespace littermap::test
