#pragma once
// A ray-cast RGB-D frame of a ground plane (optionally sloped) with axis-aligned boxes on it,
// seen by a Kinect-like camera 0.5 m up and pitched 25 degrees down, as on the park robot:
// known answers for the segmentation tests.

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/pose3.hpp"
#include "detect/camera_intrinsics.hpp"
#include "sim/camera_model.hpp"

namespace littermap::test {

struct SceneBox {
  Eigen::Vector3d min_m, max_m;  // level frame
  cv::Vec3b colour_bgr;
};

struct SyntheticScene {
  double slope_deg = 0;  // ground rises along x by this angle
  std::vector<SceneBox> boxes;
  cv::Vec3b ground_bgr{40, 140, 60};
  int colour_noise = 12;
  double depth_noise_per_m2 = 1.0e-3;
  unsigned seed = 1;
};

inline Eigen::Isometry3d CameraPose() {
  return MakeIsometry({0.2, 0, 0.5}, {0, 25.0 * M_PI / 180.0, 0}) * T_body_optical();
}

// Fills colour (CV_8UC3) and depth (CV_16UC1, mm) for the intrinsics.
inline void RenderScene(const SyntheticScene& scene, const detect::CameraIntrinsics& K,
                        cv::Mat* colour, cv::Mat* depth_mm) {
  const Eigen::Isometry3d T = CameraPose();
  const double slope = std::tan(scene.slope_deg * M_PI / 180.0);
  std::mt19937 random(scene.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  *colour = cv::Mat(K.height, K.width, CV_8UC3);
  *depth_mm = cv::Mat(K.height, K.width, CV_16UC1, cv::Scalar(0));
  for (int v = 0; v < K.height; ++v) {
    for (int u = 0; u < K.width; ++u) {
      const Eigen::Vector3d ray_camera((u - K.cx) / K.fx, (v - K.cy) / K.fy, 1.0);
      const Eigen::Vector3d origin = T.translation();
      const Eigen::Vector3d ray = T.linear() * ray_camera;  // t along ray = optical depth
      double best_t = std::numeric_limits<double>::infinity();
      cv::Vec3b best_colour(200, 200, 230);  // sky
      // Ground z = slope * x.
      const double denominator = ray.z() - slope * ray.x();
      if (denominator < 0) {
        const double t = (slope * origin.x() - origin.z()) / denominator;
        if (t > 0) best_t = t, best_colour = scene.ground_bgr;
      }
      for (const SceneBox& box : scene.boxes) {  // slab test
        double t0 = 0, t1 = std::numeric_limits<double>::infinity();
        for (int a = 0; a < 3; ++a) {
          const double ta = (box.min_m[a] - origin[a]) / ray[a];
          const double tb = (box.max_m[a] - origin[a]) / ray[a];
          t0 = std::max(t0, std::min(ta, tb));
          t1 = std::min(t1, std::max(ta, tb));
        }
        if (t0 <= t1 && t0 < best_t) best_t = t0, best_colour = box.colour_bgr;
      }
      cv::Vec3b c = best_colour;
      for (int k = 0; k < 3; ++k) {
        c[k] = cv::saturate_cast<std::uint8_t>(c[k] + scene.colour_noise * noise(random));
      }
      colour->at<cv::Vec3b>(v, u) = c;
      if (std::isfinite(best_t) && best_t < 6.0) {
        const double z = best_t + scene.depth_noise_per_m2 * best_t * best_t * noise(random);
        depth_mm->at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(std::lround(1000.0 * z));
      }
    }
  }
}

}  // namespace littermap::test
