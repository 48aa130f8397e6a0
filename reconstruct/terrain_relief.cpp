#include "reconstruct/terrain_relief.hpp"

#include <algorithm>
#include <cmath>

namespace littermap::reconstruct {

double TerrainRelief::Add(const PlanarPose& T_odom_base, double z_m) {
  if (started_) path_m_ += std::hypot(T_odom_base.x_m - last_.x_m, T_odom_base.y_m - last_.y_m);
  started_ = true;
  last_ = T_odom_base;
  samples_.push_back({path_m_, z_m});
  while (samples_.size() > 1 && path_m_ - samples_[1].path_m >= window_m_) samples_.pop_front();
  const auto [low, high] =
      std::minmax_element(samples_.begin(), samples_.end(),
                          [](const Sample& a, const Sample& b) { return a.z_m < b.z_m; });
  return high->z_m - low->z_m;
}

}  // namespace littermap::reconstruct
