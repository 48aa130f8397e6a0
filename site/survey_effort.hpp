#pragma once
// Survey effort: how many runs observed each ground cell within detection range. A run's
// camera footprint is the union, along its trajectory, of the ground sectors the camera saw:
// bearings within half the horizontal field of view of the camera's heading, and distances
// between the nearest ground point in view (set by mount height, pitch and vertical field of
// view) and the farther of the detection range and the farthest ground point in view.
// A cell counts once per run however often that run saw it: effort is in surveys.

#include <cstdint>
#include <span>
#include <vector>

#include "core/planar_pose.hpp"
#include "heatmap/raster.hpp"

namespace littermap::site {

struct CameraFootprintOptions {
  // Defaults: the Kinect-class RGB-D camera of the sample robot (640 x 480, f = 525 px, so
  // 2 atan(320/525) = 62.7 deg by 2 atan(240/525) = 49.1 deg), 0.5 m high, 25 deg down, 0.2 m
  // ahead of base_link.
  double horizontal_fov_deg = 62.7;
  double vertical_fov_deg = 49.1;
  double mount_height_m = 0.5;         // optical centre above the ground
  double mount_pitch_down_deg = 25.0;  // optical axis below the horizon
  double mount_x_m = 0.2;              // camera position and heading on the robot base
  double mount_y_m = 0.0;
  double mount_yaw_deg = 0.0;
  double max_detection_range_m = 4.0;  // litter farther away is not detected reliably
  double pose_step_m = 0.25;           // footprints every this much travel ...
  double pose_step_deg = 5.0;          // ... or this much turning (interpolated)
};

struct FootprintSector {
  double near_m = 0.0;
  double far_m = 0.0;
  double half_fov_rad = 0.0;
};

// The ground sector a camera with these options observes; throws UsageError for bad options.
FootprintSector GroundSector(const CameraFootprintOptions& options);

struct RunCoverage {
  std::vector<std::uint8_t> observed;  // 1 per grid cell the run observed, row-major
  std::size_t observed_cells = 0;
  double observed_area_m2 = 0.0;
  std::size_t footprints = 0;  // camera poses rasterised (after interpolation)
};

// T_site_base poses of one run, in time order, in the grid's coordinates.
RunCoverage CoverRun(const heatmap::GridGeometry& grid, std::span<const PlanarPose> trajectory,
                     const CameraFootprintOptions& options);

// Adds one run's coverage to an effort raster (surveys per cell).
void AddCoverage(heatmap::Raster& effort, const RunCoverage& coverage);

}  // namespace littermap::site
