#pragma once
// A simulated Kinect-like RGB-D camera that renders the simulated park (sim/world.hpp): a
// software rasteriser draws the terrain in view and every object primitive into a z-buffer, a
// deferred shading pass colours it with procedural textures under a sun, and the depth channel
// gets the Kinect's range limits, dropouts, noise and quantisation (sim/depth_sensor_model.hpp).
// Per-pixel instance ids give ground-truth segmentation masks. Deterministic: the same world,
// pose, options and frame seed give identical images.
//
//   RgbdCamera camera(world, options);        // precomputes ground types and shadows (~0.2 s)
//   RgbdRender frame = camera.Render(T_world_camera, frame_index);

#include <cstdint>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "sim/camera_model.hpp"
#include "sim/colour_image.hpp"
#include "sim/depth_sensor_model.hpp"
#include "sim/ground_map.hpp"
#include "sim/scene_tessellation.hpp"
#include "sim/surface_shading.hpp"
#include "sim/world.hpp"
#include "sim/zbuffer.hpp"

namespace littermap::sim {

struct RgbdCameraOptions {
  PinholeCamera intrinsics;  // 640x480, fx = fy = 525
  DepthSensorOptions depth;  // range 0.5..4.5 m, σ(z) = 1.425e-3 z², 1/8 px disparity steps
  double colour_noise_sigma_dn = 2.0;  // per channel, 8-bit digital numbers; 0 disables
  double sun_elevation_deg = 50;
  double sun_azimuth_deg = 35;  // counter-clockwise from world +x
  double near_clip_m = 0.05;
  double colour_range_m = 40;             // geometry farther than this is sky/haze
  bool output_instance_ids = true;        // false: RgbdRender::instance_ids stays empty
  int instance_mask_every_n_frames = 10;  // for recorders: which frames keep ground truth
  std::uint64_t seed = 1;                 // mixed with the frame seed for all sensor noise
  TessellationOptions tessellation;
};

// Throws std::invalid_argument naming the field.
void ValidateRgbdCameraOptions(const RgbdCameraOptions& options);

// Whether frame `frame_index` should be recorded with its instance mask (every n-th, from 0).
bool WantsInstanceMask(std::int64_t frame_index, const RgbdCameraOptions& options);

struct RgbdRenderStats {
  int objects_drawn = 0;  // primitives inside the view frustum
  std::int64_t triangles_rasterised = 0;
  DepthStats depth;
  double raster_ms = 0, shade_ms = 0, depth_ms = 0;
};

struct RgbdRender {
  cv::Mat colour_bgr;  // CV_8UC3
  cv::Mat depth_mm;    // CV_16UC1, 0 = no reading
  // CV_32SC1: kSkyInstance (-1) = sky / nothing, kGroundInstance (0) = ground, otherwise
  // InstanceIdOf(object) = object id + 1 (see sim/scene_tessellation.hpp).
  cv::Mat instance_ids;
  RgbdRenderStats stats;
};

class RgbdCamera {
 public:
  // Keeps a reference to `world`, which must outlive the camera.
  RgbdCamera(const World& world, RgbdCameraOptions options);

  // Renders the view of a camera at T_world_camera (optical frame: z forward, x right, y down).
  RgbdRender Render(const Eigen::Isometry3d& T_world_camera, std::uint64_t frame_seed);

  const RgbdCameraOptions& options() const { return options_; }

 private:
  const World& world_;
  RgbdCameraOptions options_;
  Lighting lighting_;
  GroundMap ground_;
  std::vector<ObjectSurface> surfaces_;
  ZBuffer zbuffer_;
};

// One-shot convenience: builds an RgbdCamera (precomputation included) and renders one frame.
RgbdRender RenderRgbd(const World& world, const Eigen::Isometry3d& T_world_camera,
                      const RgbdCameraOptions& options, std::uint64_t frame_seed);

}  // namespace littermap::sim
