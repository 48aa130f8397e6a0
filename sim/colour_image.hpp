#pragma once
// The colour channel of the simulated RGB-D camera: deferred shading of the z-buffer (every
// pixel's surface point follows from its depth), with a sun plus sky light, tree shadows and
// drifting cloud shade, aerial haze, sRGB encoding and Gaussian sensor noise.

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "sim/camera_model.hpp"
#include "sim/ground_map.hpp"
#include "sim/surface_shading.hpp"
#include "sim/zbuffer.hpp"

namespace littermap::sim {

struct Lighting {
  Eigen::Vector3d sun_direction_world = Eigen::Vector3d(0.5, 0.35, 0.8).normalized();
  float sun_irradiance = 0.9f;   // direct sun on a surface facing it
  float sky_irradiance = 0.35f;  // diffuse sky light on an upward surface
  float haze_distance_m = 250;   // e-folding distance of aerial perspective
};

struct ColourScene {
  const GroundMap& ground;
  const std::vector<ObjectSurface>& surfaces;  // indexed by object id
  Lighting lighting;
};

// CV_8UC3 BGR image of the z-buffer seen from T_world_camera; `noise_sigma_dn` is the standard
// deviation of the per-channel sensor noise in 8-bit digital numbers.
cv::Mat ShadeColour(const ZBuffer& zbuffer, const PinholeCamera& camera,
                    const Eigen::Isometry3d& T_world_camera, const ColourScene& scene,
                    double noise_sigma_dn, std::uint64_t seed);

}  // namespace littermap::sim
