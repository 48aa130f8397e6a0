#pragma once
// The simulated RGB-D camera without noise, quantisation or edge dropouts: rendering tests
// compare pixels with what the scene should show.

#include "sim/rgbd_camera.hpp"

namespace littermap::sim {

inline RgbdCameraOptions NoiselessCameraOptions() {
  RgbdCameraOptions options;
  options.depth.noise_coefficient_per_m = 0;
  options.depth.quantise = false;
  options.depth.edge_dropout_probability = 0;
  options.colour_noise_sigma_dn = 0;
  return options;
}

}  // namespace littermap::sim
