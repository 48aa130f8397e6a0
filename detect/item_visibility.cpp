#include "detect/item_visibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace littermap::detect {

bool FrameCouldSee(const ProcessedFrame& frame, const Eigen::Vector3d& position_world_m,
                   double size_m, const ItemVisibilityOptions& options) {
  if (!frame.segmentation.ground_found) return false;  // no objects are looked for without it
  const Eigen::Vector3d p_camera = frame.T_world_camera.inverse() * position_world_m;
  const double z = p_camera.z();
  if (z < options.min_depth_m || z > options.max_depth_m - options.far_margin_m) return false;
  if (frame.intrinsics.fx * size_m / z < options.min_object_px) return false;
  const Eigen::Vector2d uv = frame.intrinsics.Project(p_camera);
  const cv::Mat& depth_mm = frame.frame.depth_mm;
  const int u = static_cast<int>(std::lround(uv.x())), v = static_cast<int>(std::lround(uv.y()));
  const int w = options.depth_window_px;
  if (u < options.border_px || v < options.border_px || u >= depth_mm.cols - options.border_px ||
      v >= depth_mm.rows - options.border_px) {
    return false;
  }
  std::vector<std::uint16_t> readings;
  for (int y = std::max(0, v - w); y <= std::min(depth_mm.rows - 1, v + w); ++y) {
    for (int x = std::max(0, u - w); x <= std::min(depth_mm.cols - 1, u + w); ++x) {
      const std::uint16_t d = depth_mm.at<std::uint16_t>(y, x);
      if (d > 0) readings.push_back(d);
    }
  }
  if (readings.empty()) return false;  // no depth there: nothing can be segmented
  const auto middle = readings.begin() + static_cast<long>(readings.size() / 2);
  std::nth_element(readings.begin(), middle, readings.end());
  return 1e-3 * double(*middle) >= z - options.occlusion_margin_m;
}

}  // namespace littermap::detect
