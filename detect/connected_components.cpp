#include "detect/connected_components.hpp"

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "core/error.hpp"

namespace littermap::detect {
namespace {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) {
    for (std::size_t i = 0; i < n; ++i) parent_[i] = static_cast<int>(i);
  }
  int Find(int i) {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];  // path halving
      i = parent_[i];
    }
    return i;
  }
  void Union(int a, int b) {
    a = Find(a);
    b = Find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

struct Thresholds {
  float cos_strict;
  float cos_loose;
  int colour_sum;  // over three channels
  float gap;
  float gap_per_m;
};

bool Connected(const OrganizedCloud& cloud, const cv::Vec3b* colour, int a, int b,
               const Thresholds& t) {
  if (!cloud.HasNormal(b)) return false;
  const std::size_t ia = static_cast<std::size_t>(a), ib = static_cast<std::size_t>(b);
  const float max_gap = t.gap + t.gap_per_m * cloud.depth_m[ia];
  if ((cloud.points_m[ia] - cloud.points_m[ib]).squaredNorm() > max_gap * max_gap) return false;
  const float cosine = cloud.normals[ia].dot(cloud.normals[ib]);
  if (cosine >= t.cos_strict) return true;
  if (cosine < t.cos_loose) return false;
  const cv::Vec3b& ca = colour[ia];
  const cv::Vec3b& cb = colour[ib];
  const int distance = std::abs(ca[0] - cb[0]) + std::abs(ca[1] - cb[1]) + std::abs(ca[2] - cb[2]);
  return distance < t.colour_sum;
}

}  // namespace

void ComponentOptions::Validate() const {
  if (!(max_normal_angle_deg > 0) || !(colour_normal_angle_deg >= 0) ||
      max_normal_angle_deg + colour_normal_angle_deg >= 90) {
    throw UsageError("segmentation: need 0 < max_normal_angle_deg + colour_normal_angle_deg < 90");
  }
  if (!(max_colour_distance >= 0) || !(max_gap_m > 0) || !(max_gap_per_m >= 0)) {
    throw UsageError("segmentation: colour distance and gaps must be positive");
  }
}

Components LabelComponents(const OrganizedCloud& cloud, const cv::Mat& colour_bgr,
                           const ComponentOptions& options) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  const Thresholds t{
      static_cast<float>(std::cos(options.max_normal_angle_deg * kDeg)),
      static_cast<float>(
          std::cos((options.max_normal_angle_deg + options.colour_normal_angle_deg) * kDeg)),
      static_cast<int>(3 * options.max_colour_distance), static_cast<float>(options.max_gap_m),
      static_cast<float>(options.max_gap_per_m)};
  const auto* colour = colour_bgr.ptr<cv::Vec3b>(0);
  const int n = cloud.width * cloud.height;
  UnionFind sets(static_cast<std::size_t>(n));
  // Pass 1: join each point with its left and upper neighbour.
  for (int v = 0; v < cloud.height; ++v) {
    for (int u = 0; u < cloud.width; ++u) {
      const int i = cloud.Index(u, v);
      if (!cloud.HasNormal(i)) continue;
      if (u > 0 && Connected(cloud, colour, i, i - 1, t)) sets.Union(i, i - 1);
      if (v > 0 && Connected(cloud, colour, i, i - cloud.width, t)) sets.Union(i, i - cloud.width);
    }
  }
  // Pass 2: compact the roots into consecutive labels.
  Components out;
  out.labels.assign(static_cast<std::size_t>(n), -1);
  std::vector<int> label_of_root(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i) {
    if (!cloud.HasNormal(i)) continue;
    int& label = label_of_root[static_cast<std::size_t>(sets.Find(i))];
    if (label < 0) {
      label = static_cast<int>(out.sizes.size());
      out.sizes.push_back(0);
    }
    out.labels[static_cast<std::size_t>(i)] = label;
    ++out.sizes[static_cast<std::size_t>(label)];
  }
  return out;
}

}  // namespace littermap::detect
