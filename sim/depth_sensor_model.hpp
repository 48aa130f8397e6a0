#pragma once
// The depth channel of a Kinect-like structured-light sensor, applied to the z-buffer's exact
// depths: range limits, missing returns at grazing incidence and at depth discontinuities, axial
// noise growing with the square of the depth and disparity quantisation.
//
// Noise: σ(z) = 1.425e-3 · z² m (Khoshelham & Elberink 2012, "Accuracy and resolution of Kinect
// depth data for indoor mapping applications", Sensors 12(2), eq. 14 and fig. 8).
// Quantisation: the Kinect measures disparity d = f·b / z in 1/8-pixel steps (f ≈ 580 px for the
// IR camera, b ≈ 0.075 m), so depth steps grow as Δz ≈ z² · Δd / (f·b): 2.9 mm at 1 m, 7 cm at
// 5 m, as K&E report. Depth is quantised by rounding the disparity to its step.

#include <cstdint>

#include <opencv2/core.hpp>

#include "sim/camera_model.hpp"
#include "sim/zbuffer.hpp"

namespace littermap::sim {

struct DepthSensorOptions {
  double min_depth_m = 0.5;                   // Kinect v1 working range for mapping
  double max_depth_m = 4.5;                   // beyond: 0 (no reading)
  double noise_coefficient_per_m = 1.425e-3;  // σ(z) = coefficient · z²; 0 disables noise
  bool quantise = true;
  double disparity_step_px = 1.0 / 8;
  double baseline_m = 0.075;
  double disparity_focal_px = 580;
  double max_incidence_deg = 80;          // steeper surfaces return nothing
  double edge_jump_fraction = 0.05;       // a neighbour this much (of z) nearer/farther is an edge
  double edge_dropout_probability = 0.5;  // chance an edge pixel has no reading
};

struct DepthStats {
  int valid = 0;         // pixels with a reading
  int out_of_range = 0;  // sky, nearer than min or farther than max
  int grazing = 0;       // dropped for grazing incidence
  int edge = 0;          // dropped at a depth discontinuity
};

// Depth image in millimetres (CV_16UC1, 0 = no reading) of the z-buffer. Deterministic in
// (zbuffer, options, seed).
cv::Mat SimulateDepth(const ZBuffer& zbuffer, const PinholeCamera& camera,
                      const DepthSensorOptions& options, std::uint64_t seed, DepthStats& stats);

// Validates the options; throws std::invalid_argument naming the field.
void ValidateDepthSensorOptions(const DepthSensorOptions& options);

}  // namespace littermap::sim
