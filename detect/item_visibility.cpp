#include "detect/item_visibility.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

constexpr std::size_t kMaxDepthWindow = 81;  // (2 * 4 + 1)^2

}  // namespace

void ItemVisibilityOptions::Validate() const {
  RequireOption(min_depth_m >= 0 && max_depth_m - far_margin_m > min_depth_m, "detect",
                "max_depth_m - far_margin_m", "> min_depth_m >= 0");
  RequireOption(border_px >= 0, "detect", "border_px", ">= 0");
  RequireOption(depth_window_px >= 0 && depth_window_px <= 4, "detect", "depth_window_px",
                "from 0 to 4");
}

FrameVisibility::FrameVisibility(const ProcessedFrame& frame, const ItemVisibilityOptions& options)
    : frame_(frame),
      options_((options.Validate(), options)),
      T_camera_world_(frame.T_world_camera.inverse()) {}

bool FrameVisibility::CouldSee(const Eigen::Vector3d& position_world_m, double size_m) const {
  if (!frame_.segmentation.ground_found) return false;  // no objects are looked for without it
  const Eigen::Vector3d p_camera = T_camera_world_ * position_world_m;
  const double z = p_camera.z();
  if (z < options_.min_depth_m || z > options_.max_depth_m - options_.far_margin_m) return false;
  if (frame_.intrinsics.fx * size_m / z < options_.min_object_px) return false;
  const Eigen::Vector2d uv = frame_.intrinsics.Project(p_camera);
  const cv::Mat& depth_mm = frame_.frame.depth_mm;
  const int u = static_cast<int>(std::lround(uv.x())), v = static_cast<int>(std::lround(uv.y()));
  const int border = std::max(options_.border_px, options_.depth_window_px);
  if (u < border || v < border || u >= depth_mm.cols - border || v >= depth_mm.rows - border) {
    return false;
  }
  std::array<std::uint16_t, kMaxDepthWindow> readings;
  std::size_t count = 0;
  const int w = options_.depth_window_px;
  for (int y = v - w; y <= v + w; ++y) {
    const auto* row = depth_mm.ptr<std::uint16_t>(y);
    for (int x = u - w; x <= u + w; ++x) {
      if (row[x] > 0) readings[count++] = row[x];
    }
  }
  if (count == 0) return false;  // no depth there: nothing can be segmented
  const auto middle = readings.begin() + static_cast<long>(count / 2);
  std::nth_element(readings.begin(), middle, readings.begin() + static_cast<long>(count));
  if (1e-3 * double(*middle) < z - options_.occlusion_margin_m) return false;
  // Something was cut out there (an object too large with its neighbour, or clutter this time):
  // the frame saw an object at the place, not ground.
  const cv::Mat& non_ground = frame_.segmentation.refinement.non_ground;
  if (non_ground.empty()) return true;
  return cv::countNonZero(non_ground(cv::Rect(u - w, v - w, 2 * w + 1, 2 * w + 1))) == 0;
}

}  // namespace littermap::detect
