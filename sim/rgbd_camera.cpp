#include "sim/rgbd_camera.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/procedural_noise.hpp"

namespace littermap::sim {
namespace {

Lighting MakeLighting(const RgbdCameraOptions& options) {
  const double deg = std::numbers::pi / 180;
  const double elevation = options.sun_elevation_deg * deg, azimuth = options.sun_azimuth_deg * deg;
  Lighting lighting;
  lighting.sun_direction_world = {std::cos(elevation) * std::cos(azimuth),
                                  std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
  return lighting;
}

double MillisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

void ValidateRgbdCameraOptions(const RgbdCameraOptions& o) {
  const auto require = [](bool ok, const char* field) {
    if (!ok) throw std::invalid_argument(std::string("rgbd camera: invalid ") + field);
  };
  const PinholeCamera& k = o.intrinsics;
  require(k.width > 0 && k.height > 0 && k.fx > 0 && k.fy > 0, "intrinsics");
  ValidateDepthSensorOptions(o.depth);
  require(o.colour_noise_sigma_dn >= 0, "colour_noise_sigma_dn");
  require(o.sun_elevation_deg > 0 && o.sun_elevation_deg <= 90, "sun_elevation_deg");
  require(o.near_clip_m > 0 && o.near_clip_m < o.depth.min_depth_m, "near_clip_m");
  require(o.colour_range_m > o.depth.max_depth_m, "colour_range_m");
  require(o.instance_mask_every_n_frames >= 1, "instance_mask_every_n_frames");
  require(o.tessellation.ground_columns >= 4 && o.tessellation.ring_spacing_m > 0 &&
              o.tessellation.ring_growth >= 0,
          "tessellation");
}

bool WantsInstanceMask(std::int64_t frame_index, const RgbdCameraOptions& options) {
  return frame_index % options.instance_mask_every_n_frames == 0;
}

RgbdCamera::RgbdCamera(const World& world, RgbdCameraOptions options)
    : world_(world),
      options_((ValidateRgbdCameraOptions(options), std::move(options))),
      lighting_(MakeLighting(options_)),
      ground_(world, lighting_.sun_direction_world),
      surfaces_(MakeObjectSurfaces(world)),
      zbuffer_(options_.intrinsics, float(options_.near_clip_m), float(options_.colour_range_m)) {}

RgbdRender RgbdCamera::Render(const Eigen::Isometry3d& T_world_camera, std::uint64_t frame_seed) {
  RgbdRender render;
  const std::uint64_t seed = Hash3(options_.seed, frame_seed, 0xCA3E);
  auto start = std::chrono::steady_clock::now();
  zbuffer_.Clear();
  DrawTerrain(world_.terrain, T_world_camera, options_.intrinsics, options_.tessellation,
              options_.colour_range_m, zbuffer_);
  render.stats.objects_drawn =
      DrawObjects(world_.objects, T_world_camera, options_.intrinsics, options_.tessellation,
                  float(options_.colour_range_m), zbuffer_);
  render.stats.triangles_rasterised = zbuffer_.triangles_drawn();
  render.stats.raster_ms = MillisecondsSince(start);

  start = std::chrono::steady_clock::now();
  const ColourScene scene{ground_, surfaces_, lighting_};
  render.colour_bgr = ShadeColour(zbuffer_, options_.intrinsics, T_world_camera, scene,
                                  options_.colour_noise_sigma_dn, HashMix(seed + 1));
  render.stats.shade_ms = MillisecondsSince(start);

  start = std::chrono::steady_clock::now();
  render.depth_mm = SimulateDepth(zbuffer_, options_.intrinsics, options_.depth, HashMix(seed + 2),
                                  render.stats.depth);
  if (options_.output_instance_ids) {
    render.instance_ids = cv::Mat(zbuffer_.height(), zbuffer_.width(), CV_32SC1,
                                  const_cast<std::int32_t*>(zbuffer_.ids().data()))
                              .clone();
  }
  render.stats.depth_ms = MillisecondsSince(start);
  return render;
}

RgbdRender RenderRgbd(const World& world, const Eigen::Isometry3d& T_world_camera,
                      const RgbdCameraOptions& options, std::uint64_t frame_seed) {
  RgbdCamera camera(world, options);
  return camera.Render(T_world_camera, frame_seed);
}

}  // namespace littermap::sim
