#pragma once
// One-shot texture learning and graph-cut refinement of the ground (thesis 3.1, Alg. 3.1.4.1,
// steps 3-5). Geometry labels each pixel of the ground's image region as certain ground, certain
// non-ground (standing above the ground surface) or uncertain (near the surface but off the
// ground component, ground-coloured unlike the ground, or without depth). K-means-initialised
// colour GMMs of the certain ground and non-ground are learnt from this very frame, and a
// max-flow/min-cut over the uncertain pixels minimises the Gibbs energy
//   E = sum_i D_i(label_i) + sum_{i~j, label_i != label_j} gamma * exp(-beta |c_i - c_j|^2)
// with D = -log p(colour | label) plus a height term for points above the surface. One pass.

#include <cstddef>
#include <cstdint>

#include <opencv2/core.hpp>

#include "detect/ground_surface.hpp"
#include "detect/organized_cloud.hpp"

namespace littermap::detect {

// Per-pixel labels of the refinement (CV_8U).
enum PixelLabel : std::uint8_t {
  kOutside = 0,    // outside the ground's image region: not examined
  kGround = 1,     // certain ground
  kNonGround = 2,  // certain non-ground: stands above the surface
  kUncertain = 3,  // left to the graph cut
};

struct TextureRefinementOptions {
  int gmm_components = 5;  // K of the K-means initialisation and of each GMM
  // Colours per model, sampled evenly: 80 per component describe a surface; OpenCV's EM costs
  // about 3 us per colour, and 800 took 5 ms a frame for no better segmentation (IoU 0.616 with
  // 800, 0.636 with 400 on a park seed).
  int max_training_pixels = 400;
  // Depth noise sigma(z) = depth_noise_per_m2 * z^2 (Kinect, Khoshelham & Elberink 2012).
  double depth_noise_per_m2 = 1.5e-3;
  double min_ground_band_m = 0.015;   // |height| a certain-ground point may have at least
  double min_object_height_m = 0.01;  // above the band: certain non-ground
  // A point this far below the ground surface is off this ground (the floor beyond a table's
  // edge, the far side of a ditch): neither ground nor an object on it, so not examined.
  double max_depth_below_ground_m = 0.15;
  // A ground-component pixel whose colour is this much (log) likelier under the non-ground
  // model becomes uncertain: flat litter lies on the ground component.
  double colour_anomaly_log_ratio = 1.0;
  // The region examined: the ground's image box, grown upwards by this many pixels so that an
  // object standing at the far edge of the ground is examined whole (only its pixels with depth).
  int region_margin_px = 40;
  double smoothness_weight = 25.0;  // gamma (4-neighbourhood)
  double height_weight = 3.0;       // per band of height above the surface, capped at 3 bands
  // Fewer certain non-ground pixels than this: the non-ground model is uniform over colours.
  int min_nonground_training_pixels = 200;
  void Validate() const;
};

struct TextureRefinementResult {
  cv::Mat labels;      // CV_8U PixelLabel before the cut
  cv::Mat non_ground;  // CV_8U 255 = non-ground after the cut (inside the region only)
  cv::Rect region;     // the ground's image bounding box
  std::size_t uncertain = 0;
  std::size_t cut_to_non_ground = 0;
  bool non_ground_model_learnt = false;
};

TextureRefinementResult RefineGroundByTexture(const cv::Mat& colour_bgr,
                                              const OrganizedCloud& cloud,
                                              const GroundResult& ground,
                                              const TextureRefinementOptions& options);

}  // namespace littermap::detect
