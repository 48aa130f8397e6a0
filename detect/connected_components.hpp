#pragma once
// Connected-component labelling of an organized cloud (thesis 3.1, step 2): two passes with
// union-find over the 4-neighbourhood. Two neighbouring points connect when they are close in
// space and their normals agree, or agree a little less but their colours are close:
//   gap < max_gap(z)  and  (angle < t_n  or  (angle < t_n + alpha  and  colour_dist < t_c)).

#include <vector>

#include <opencv2/core.hpp>

#include "detect/organized_cloud.hpp"

namespace littermap::detect {

struct ComponentOptions {
  double max_normal_angle_deg = 8.0;     // t_n
  double colour_normal_angle_deg = 8.0;  // alpha: extra angle allowed for similar colours
  double max_colour_distance = 30.0;     // t_c: mean absolute BGR difference, 0..255
  // Largest 3D gap between neighbours: a floor plus a share of the depth (the pixel footprint
  // and the depth noise both grow with range).
  double max_gap_m = 0.02;
  double max_gap_per_m = 0.02;
  void Validate() const;
};

struct Components {
  std::vector<int> labels;  // per pixel, -1 where the cloud has no point or normal
  std::vector<int> sizes;   // points per label
};

// colour_bgr: CV_8UC3 of the cloud's size.
Components LabelComponents(const OrganizedCloud& cloud, const cv::Mat& colour_bgr,
                           const ComponentOptions& options);

}  // namespace littermap::detect
